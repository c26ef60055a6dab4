// Surface materials (host+device POD): one record for every kind, a tag and a switch where it is
// used (integrators/bsdf.h). Any kind may also emit.
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

enum class MaterialKind : uint32_t {
    Lambertian,  ///< diffuse: albedo / pi
    Glossy,      ///< diffuse plus a normalised Phong lobe (Lafortune and Willems 1994)
    Mirror,      ///< perfect specular reflection, tinted by albedo
    Glass,       ///< thin dielectric pane: Schlick-Fresnel reflection, straight transmission tinted by albedo
    Water        ///< the surface of a body of water (air above, +y): exact Fresnel, refraction, waves (Material::water)
};

/// What a Water material adds to the interface (integrators/water.h reads it).
struct WaterOptics {
    Vec3f absorption{0, 0, 0};   ///< 1/m along a path below the surface (Beer-Lambert)
    float windX = 0, windZ = 0;  ///< the wind's velocity over the water, m/s, towards world +x (east) and +z (south): the waves
    /// Metres below the surface that a refracted ray passes unseen: on the flat ground, the layer down
    /// to the ground's plane, which holds the ground cover that the water covers. 0 where the bed is the
    /// terrain itself.
    float skipBelow = 0;
};

struct Material {
    Vec3f albedo{0.8f, 0.8f, 0.8f};  ///< linear diffuse reflectance in [0, 1); Mirror: reflectance; Glass: transmittance
    MaterialKind kind = MaterialKind::Lambertian;
    Vec3f specular{0, 0, 0};         ///< Glossy: reflectance of the lobe; albedo + specular <= 1 per channel
    float exponent = 1.0f;           ///< Glossy: Phong exponent
    Vec3f emission{0, 0, 0};         ///< radiance emitted from both sides
    float ior = 1.5f;                ///< Glass: index of refraction, for Schlick's R0; Water: of the water
    WaterOptics water{};             ///< Water: absorption, waves
};

/// Reflectance of a Glass material's pane at `cosine` (of either side) with its normal: Schlick's
/// approximation (Schlick 1994) of the Fresnel reflectance for the material's ior.
URBIS_HD inline float glassFresnel(const Material& m, float cosine) {
    float r0 = (m.ior - 1.0f) / (m.ior + 1.0f);
    r0 *= r0;
    const float c = 1.0f - fminf(1.0f, fabsf(cosine));
    return r0 + (1.0f - r0) * c * c * c * c * c;
}

} // namespace urbis
