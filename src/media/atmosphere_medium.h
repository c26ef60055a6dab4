// The atmosphere's medium at a height (host+device): Rayleigh and Mie densities falling off
// exponentially, ozone in a tent, and their phase functions (Hillaire 2020 § 4; Bruneton 2017).
// Heights in km above the ground sphere, coefficients per km.
#pragma once

#include "math/sampling.h"
#include "scene/atmosphere.h"

namespace urbis {

/// Scattering and extinction coefficients (per km) at one point of the medium.
struct MediumSample {
    Vec3f rayleighScattering;
    float mieScattering = 0;
    Vec3f extinction;
};

/// Density of the ozone layer (0 to 1) at height `h` km: a tent peaking at ozoneCentre.
URBIS_HD inline float ozoneDensity(const Atmosphere& a, float h) {
    return fmaxf(0.0f, 1.0f - fabsf(h - a.ozoneCentre) / a.ozoneHalfWidth);
}

/// The medium at height `h` km above the ground sphere.
URBIS_HD inline MediumSample sampleMedium(const Atmosphere& a, float h) {
    const float rayleigh = expf(-h / a.rayleighScaleHeight), mie = expf(-h / a.mieScaleHeight);
    MediumSample m;
    m.rayleighScattering = a.rayleighScattering * rayleigh;
    m.mieScattering = a.mieScattering * mie;
    const float mieExtinction = (a.mieScattering + a.mieAbsorption) * mie;
    m.extinction = m.rayleighScattering + a.ozoneAbsorption * ozoneDensity(a, h) +
                   Vec3f{mieExtinction, mieExtinction, mieExtinction};
    return m;
}

/// Rayleigh's phase function per steradian, for the cosine between the light's travel and the view's
/// reversed direction (both towards the light: cosTheta = dot(view direction, direction to the sun)).
URBIS_HD inline float rayleighPhase(float cosTheta) { return 3.0f / (16.0f * kPi) * (1.0f + cosTheta * cosTheta); }

/// The Cornette-Shanks phase function for Mie scattering (Hillaire 2020 § 4, eq. 4), per steradian,
/// with cosTheta as for rayleighPhase.
URBIS_HD inline float miePhase(float g, float cosTheta) {
    const float k = 3.0f / (8.0f * kPi) * (1.0f - g * g) / (2.0f + g * g);
    const float denom = 1.0f + g * g - 2.0f * g * cosTheta;
    return k * (1.0f + cosTheta * cosTheta) / (denom * sqrtf(denom));
}

/// Distance (km) from radius `r` along a ray of zenith cosine `mu` to the sphere of radius `radius`
/// around the planet's centre, where the ray leaves it (r inside) or enters it first (r outside;
/// negative when missed).
URBIS_HD inline float distanceToSphere(float r, float mu, float radius, bool nearest) {
    const float disc = r * r * (mu * mu - 1.0f) + radius * radius;
    if (disc < 0.0f) return -1.0f;
    const float root = sqrtf(disc);
    return nearest ? -r * mu - root : -r * mu + root;
}

/// Whether a ray from radius `r` (km) of zenith cosine `mu` meets the ground sphere.
URBIS_HD inline bool rayMeetsGround(const Atmosphere& a, float r, float mu) {
    return mu < 0.0f && r * r * (mu * mu - 1.0f) + a.bottomRadius * a.bottomRadius >= 0.0f;
}

} // namespace urbis
