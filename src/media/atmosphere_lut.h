// The atmosphere's look-up tables (host+device): how each maps its parameters to table coordinates
// and back, and their bilinear look-up. Hillaire 2020 § 5: transmittance after Bruneton 2017 (§ 4.1,
// the distance-based parametrisation), multiple scattering over (sun zenith, height), and the sky
// view over (azimuth from the sun, latitude) with the non-linear latitude that packs texels near the
// horizon. Coordinates are in [0, 1] with the first and last texels' centres at 0 and 1 (texel i of
// n holds coordinate i / (n - 1)), so that the ends of every range are stored exactly.
#pragma once

#include "media/atmosphere_medium.h"
#include "scene/scene_arrays.h"

namespace urbis {

/// Bilinear look-up of a w x h table (rows of w texels) at coordinates `c` in [0, 1] (clamped).
URBIS_HD inline Vec3f lutBilinear(ArrayView<Vec3f> lut, uint32_t w, uint32_t h, Vec2f c) {
    const float x = fminf(fmaxf(c.x, 0.0f), 1.0f) * float(w - 1), y = fminf(fmaxf(c.y, 0.0f), 1.0f) * float(h - 1);
    const uint32_t x0 = x >= float(w - 1) ? w - 2 : uint32_t(x), y0 = y >= float(h - 1) ? h - 2 : uint32_t(y);
    const float fx = x - float(x0), fy = y - float(y0);
    const Vec3f* row0 = lut.data + size_t(y0) * w + x0;
    const Vec3f* row1 = row0 + w;
    return (row0[0] * (1.0f - fx) + row0[1] * fx) * (1.0f - fy) + (row1[0] * (1.0f - fx) + row1[1] * fx) * fy;
}

/// Transmittance table coordinates of a ray from radius `r` (km) of zenith cosine `mu` that does not
/// meet the ground: x the distance to the top scaled between its least and greatest at that radius,
/// y the distance to the horizon scaled by the greatest (Bruneton 2017).
URBIS_HD inline Vec2f transmittanceLutCoord(const Atmosphere& a, float r, float mu) {
    const float H = sqrtf(a.topRadius * a.topRadius - a.bottomRadius * a.bottomRadius);
    const float rho = sqrtf(fmaxf(0.0f, r * r - a.bottomRadius * a.bottomRadius));
    const float d = fmaxf(0.0f, distanceToSphere(r, mu, a.topRadius, false));
    const float dMin = a.topRadius - r, dMax = rho + H;
    return {dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0f, rho / H};
}

/// The radius (km) and zenith cosine of transmittance table coordinates `c`: the inverse of
/// transmittanceLutCoord.
URBIS_HD inline void transmittanceLutParams(const Atmosphere& a, Vec2f c, float& r, float& mu) {
    const float H = sqrtf(a.topRadius * a.topRadius - a.bottomRadius * a.bottomRadius);
    const float rho = H * c.y;
    r = sqrtf(rho * rho + a.bottomRadius * a.bottomRadius);
    const float dMin = a.topRadius - r, dMax = rho + H;
    const float d = dMin + c.x * (dMax - dMin);
    mu = d == 0.0f ? 1.0f : fminf(1.0f, fmaxf(-1.0f, (H * H - rho * rho - d * d) / (2.0f * r * d)));
}

/// Transmittance from radius `r` (km) along zenith cosine `mu` to the top of the atmosphere; zero
/// where the ray meets the ground (the planet's shadow).
URBIS_HD inline Vec3f transmittanceToTop(const Atmosphere& a, ArrayView<Vec3f> lut, float r, float mu) {
    if (rayMeetsGround(a, r, mu)) return {0, 0, 0};
    return lutBilinear(lut, kTransmittanceLutWidth, kTransmittanceLutHeight, transmittanceLutCoord(a, r, mu));
}

/// Multiple-scattering table coordinates at radius `r` (km) under a sun of zenith cosine `muSun`.
URBIS_HD inline Vec2f multiScatteringLutCoord(const Atmosphere& a, float r, float muSun) {
    return {0.5f * muSun + 0.5f, (r - a.bottomRadius) / (a.topRadius - a.bottomRadius)};
}

/// Radiance per unit of solar irradiance that multiple scattering brings to a point at radius `r`
/// (km) under a sun of zenith cosine `muSun`, per unit of scattering coefficient: Hillaire 2020's
/// Psi_ms (§ 5.5, eq. 10), isotropic.
URBIS_HD inline Vec3f multiScattering(const Atmosphere& a, ArrayView<Vec3f> lut, float r, float muSun) {
    return lutBilinear(lut, kMultiScatteringLutSize, kMultiScatteringLutSize, multiScatteringLutCoord(a, r, muSun));
}

/// Radius (km) from which the sky view table sees the sky: the world's origin, kept 10 m above the
/// ground sphere so that the horizon is defined (as Hillaire's PLANET_RADIUS_OFFSET).
URBIS_HD inline float skyViewRadius(const Atmosphere& a) { return a.bottomRadius + fmaxf(a.altitude, 0.01f); }

/// Sky view table coordinates of the unit world direction `dir` (y up) under the sun `a.sunDirection`:
/// x the square root of (1 - cos(azimuth from the sun)) / 2, y the latitude, non-linear (Hillaire 2020
/// § 5.3: the sky above the horizon in [0, 0.5], the ground below in [0.5, 1], texels packed near the
/// horizon where the sky changes fastest).
URBIS_HD inline Vec2f skyViewLutCoord(const Atmosphere& a, Vec3f dir) {
    const float r = skyViewRadius(a);
    const float cosBeta = sqrtf(r * r - a.bottomRadius * a.bottomRadius) / r;
    const float beta = acosf(cosBeta), zenithHorizonAngle = kPi - beta;
    const float viewZenith = acosf(fminf(1.0f, fmaxf(-1.0f, dir.y)));
    Vec2f c;
    if (!rayMeetsGround(a, r, dir.y)) {
        const float t = fminf(1.0f, viewZenith / zenithHorizonAngle);
        c.y = 0.5f * (1.0f - sqrtf(1.0f - t));
    } else {
        c.y = 0.5f + 0.5f * sqrtf(fminf(1.0f, fmaxf(0.0f, (viewZenith - zenithHorizonAngle) / beta)));
    }
    const Vec3f s = a.sunDirection;
    const float denom = sqrtf((dir.x * dir.x + dir.z * dir.z) * (s.x * s.x + s.z * s.z));
    const float cosAzimuth = denom > 1e-12f ? (dir.x * s.x + dir.z * s.z) / denom : 1.0f;
    c.x = sqrtf(fmaxf(0.0f, 0.5f - 0.5f * cosAzimuth));
    return c;
}

/// The view zenith cosine and the cosine of the azimuth from the sun of sky view table coordinates
/// `c`: the inverse of skyViewLutCoord.
URBIS_HD inline void skyViewLutParams(const Atmosphere& a, Vec2f c, float& viewZenithCos, float& cosAzimuth) {
    const float r = skyViewRadius(a);
    const float cosBeta = sqrtf(r * r - a.bottomRadius * a.bottomRadius) / r;
    const float beta = acosf(cosBeta), zenithHorizonAngle = kPi - beta;
    if (c.y < 0.5f) {
        const float t = 1.0f - 2.0f * c.y;
        viewZenithCos = cosf(zenithHorizonAngle * (1.0f - t * t));
    } else {
        const float t = 2.0f * c.y - 1.0f;
        viewZenithCos = cosf(zenithHorizonAngle + beta * t * t);
    }
    cosAzimuth = 1.0f - 2.0f * c.x * c.x;
}

} // namespace urbis
