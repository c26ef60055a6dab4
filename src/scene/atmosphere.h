// The atmosphere's record (host+device POD): Earth's Rayleigh, Mie and ozone media after Hillaire,
// "A Scalable and Production Ready Sky and Atmosphere Rendering Technique" (EGSR 2020), § 4 and
// its reference parameters (sebh/UnrealEngineSkyAtmosphere), and the sizes of its look-up tables.
// Lengths in kilometres, coefficients per kilometre; the world's y = 0 lies `altitude` above the
// ground sphere, and the world's up (+y) is the local zenith (a city is flat on the planet's scale).
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

struct Atmosphere {
    float bottomRadius = 6360.0f;                            ///< km, the ground sphere
    float topRadius = 6460.0f;                               ///< km, where the medium ends
    Vec3f rayleighScattering{5.802e-3f, 13.558e-3f, 33.1e-3f};  ///< per km at the ground
    float rayleighScaleHeight = 8.0f;                        ///< km
    float mieScattering = 3.996e-3f;                         ///< per km at the ground (aerosols)
    float mieAbsorption = 0.444e-3f;                         ///< per km at the ground
    float mieScaleHeight = 1.2f;                             ///< km
    float mieG = 0.8f;                                       ///< anisotropy of the Cornette-Shanks phase
    Vec3f ozoneAbsorption{0.650e-3f, 1.881e-3f, 0.085e-3f};  ///< per km at the layer's peak
    float ozoneCentre = 25.0f, ozoneHalfWidth = 15.0f;       ///< km: a tent from 10 to 40 km
    Vec3f groundAlbedo{0.3f, 0.3f, 0.3f};                    ///< of the ground sphere (multiple scattering)
    float altitude = 0.0f;                                   ///< km of the world's y = 0 above the ground sphere
    // Set by buildAtmosphere (media/atmosphere_build.h) from the scene's sun:
    Vec3f sunDirection{0, 1, 0};                             ///< unit, world space
    Vec3f solarIrradiance{0, 0, 0};                          ///< at the top of the atmosphere, facing the sun
};

/// Sizes of the look-up tables (Hillaire 2020 § 5): transmittance over (view zenith, height), the
/// multiple-scattering transfer over (sun zenith, height), the sky as seen from the world's origin
/// over (azimuth from the sun, latitude).
inline constexpr uint32_t kTransmittanceLutWidth = 256, kTransmittanceLutHeight = 64;
inline constexpr uint32_t kMultiScatteringLutSize = 32;
inline constexpr uint32_t kSkyViewLutWidth = 192, kSkyViewLutHeight = 108;

} // namespace urbis
