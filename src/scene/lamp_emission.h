// The colour of a lamp's light from its colour temperature (host): what the night's lights will
// emit from LampRecord::colourTemperature and luminousFlux.
#pragma once

#include "math/vec.h"

namespace urbis {

/// Linear Rec.709 colour of a blackbody at `kelvin` (clamped to 1000-40000 K), normalised to
/// luminance 1: Planck's law integrated against the CIE 1931 observer (the multi-lobe fit of
/// C. Wyman, P.-P. Sloan and P. Shirley, "Simple Analytic Approximations to the CIE XYZ Color
/// Matching Functions", JCGT 2013) from 380 to 780 nm, then XYZ to Rec.709, negative parts clipped.
/// Sodium's 2000 K is orange (r > g > b), 6500 K about white.
Vec3f blackbodyRgb(float kelvin);

} // namespace urbis
