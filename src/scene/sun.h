// The sun's record (host+device POD): a disk of uniform radiance with a finite angular radius, so
// that shadows are soft. Sampling and evaluation live in lights/sun_light.h.
#pragma once

#include "math/vec.h"

namespace urbis {

struct Sun {
    Vec3f direction{0, 1, 0};  ///< unit, world space, towards the sun
    Vec3f radiance{0, 0, 0};   ///< per steradian inside the disk; zero turns the sun off
    float cosHalfAngle = 1.0f; ///< cosine of the angular radius
};

/// A sun at elevation and azimuth (degrees; azimuth clockwise from north) whose disk of the given
/// angular radius (degrees) gives `irradiance` on a surface facing it. World: x east, y up, z south.
Sun makeSun(float elevationDeg, float azimuthDeg, float angularRadiusDeg, Vec3f irradiance);

/// The world-space unit direction for an elevation and azimuth in degrees (azimuth clockwise from north).
Vec3f directionFromElevationAzimuth(float elevationDeg, float azimuthDeg);

} // namespace urbis
