// The exact Fresnel reflectance of a smooth dielectric interface and Snell's refraction (host+device).
#pragma once

#include "math/vec.h"

namespace urbis {

/// The unpolarised Fresnel reflectance of a smooth interface between dielectrics, for light arriving
/// at `cosI` (> 0) with the normal on the side of index n_i and leaving into index n_t, eta = n_t / n_i:
/// the mean of the s and p amplitude ratios squared (Born and Wolf, Principles of Optics, 1.5.2;
/// pbrt-v4 FrDielectric). In `cosT` the cosine of the refracted direction with the normal's negative,
/// 0 under total internal reflection, where the reflectance is 1. Transmittance is 1 - reflectance.
URBIS_HD inline float fresnelDielectric(float cosI, float eta, float& cosT) {
    const float sin2T = (1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f) {
        cosT = 0.0f;
        return 1.0f;
    }
    cosT = sqrtf(1.0f - sin2T);
    const float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    const float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5f * (rs * rs + rp * rp);
}

/// The direction refracted from unit `wo` (pointing away from the surface, on the side of unit `n`)
/// into the other side, for eta = n_t / n_i and the cosT that fresnelDielectric gave (Snell's law).
URBIS_HD inline Vec3f refractDir(Vec3f wo, Vec3f n, float eta, float cosT) {
    return wo * (-1.0f / eta) + n * (dot(wo, n) / eta - cosT);
}

} // namespace urbis
