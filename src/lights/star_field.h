// The stars (host+device): procedural, from a hash per cell of an equal-area map of the celestial
// sphere, with no texture. Each cell holds a star with the probability that gives the sky its
// observed count, N(< m) = 5000 * 10^(0.5 (m - 6)) over the whole sphere (about 5,000 to magnitude 6,
// 9,000 to 6.5, a handful brighter than 0), for magnitudes -1.5 to 6.5; a star is a small disk in
// the map inside its cell, of irradiance 10^(-0.4 m) times that of magnitude 0 (2.5e-6 lux, scaled to
// the renderer's units by StarField), with a small spread of colour from orange to blue-white.
// docs/astronomy.md says more.
#pragma once

#include "math/constants.h"
#include "math/hash.h"
#include "math/vec.h"
#include "scene/night_sky.h"

#include <cstdint>

namespace urbis {

inline constexpr uint32_t kStarMapSide = 1024;       ///< cells of the map per side (each 1.2e-5 sr)
inline constexpr float kStarBrightest = -1.5f;       ///< magnitude range of the stars
inline constexpr float kStarFaintest = 6.5f;
inline constexpr float kStarsBrighterThanSix = 5000; ///< over the whole sphere
inline constexpr float kStarDiskRadius = 0.15f;      ///< of a star's disk, in cells of the map (about 0.03 degree)
inline constexpr uint32_t kStarSeed = 0x5ea5f00du;

/// Stars brighter than magnitude m over the whole sphere, by the distribution the cells draw from.
URBIS_HD inline float starsBrighterThan(float m) { return kStarsBrighterThanSix * powf(10.0f, 0.5f * (m - 6.0f)); }

/// Clarberg's equal-area map of the unit sphere onto the unit square ("Fast Equal-Area Mapping of
/// the (Hemi)Sphere using SIMD", JGT 2008; as pbrt-v4's EqualAreaSphereToSquare), with z as its
/// axis: equal areas of the square are equal solid angles, 4 pi in all.
URBIS_HD inline Vec2f equalAreaSquareFromSphere(Vec3f d) {
    const float x = fabsf(d.x), y = fabsf(d.y), z = fabsf(d.z);
    const float r = sqrtf(fmaxf(0.0f, 1.0f - z));
    const float a = fmaxf(x, y), b = fminf(x, y);
    float phi = a > 0.0f ? atanf(b / a) * (2.0f / kPi) : 0.0f;
    if (x < y) phi = 1.0f - phi;
    float v = phi * r, u = r - v;
    if (d.z < 0.0f) {
        const float swap = u;
        u = 1.0f - v;
        v = 1.0f - swap;
    }
    return {0.5f * (copysignf(u, d.x) + 1.0f), 0.5f * (copysignf(v, d.y) + 1.0f)};
}

/// The star of one cell of the map, if it holds one.
struct Star {
    bool present = false;
    Vec2f centre;        ///< in the map's unit square
    float magnitude = 0;
    Vec3f colour;        ///< linear RGB of luminance 1
};

/// The star of cell (cx, cy): a pure function of the cell.
URBIS_HD inline Star starInCell(uint32_t cx, uint32_t cy) {
    HashStream h{hash3(kStarSeed, cx, cy)};
    Star s;
    const float count = starsBrighterThan(kStarFaintest) - starsBrighterThan(kStarBrightest);
    s.present = h.uniform() < count / float(kStarMapSide * kStarMapSide);
    if (!s.present) return s;
    const float span = 1.0f - 2.0f * kStarDiskRadius, cell = 1.0f / float(kStarMapSide);
    s.centre = {(float(cx) + kStarDiskRadius + span * h.uniform()) * cell, (float(cy) + kStarDiskRadius + span * h.uniform()) * cell};
    // Inverse of the count's distribution: A = 10^(0.5 m) is uniform between its ends.
    const float lo = powf(10.0f, 0.5f * kStarBrightest), hi = powf(10.0f, 0.5f * kStarFaintest);
    s.magnitude = 2.0f * log10f(lo + (hi - lo) * h.uniform());
    // Orange (about 4000 K) to blue-white (about 9000 K), each scaled to luminance 1.
    const float t = h.uniform();
    const Vec3f warm{1.0f, 0.80f, 0.62f}, cool{0.80f, 0.88f, 1.0f};
    s.colour = warm * ((1.0f - t) / luminance(warm)) + cool * (t / luminance(cool));
    return s;
}

/// Irradiance (renderer units, luminance) of a star of magnitude m when magnitude 0 gives `zero`.
URBIS_HD inline float starIrradiance(float zero, float m) { return zero * powf(10.0f, -0.4f * m); }

/// Radiance of the stars at the point `uv` of the map: a star's irradiance spread over its disk.
URBIS_HD inline Vec3f starRadianceAt(const StarField& stars, Vec2f uv) {
    const uint32_t cx = uint32_t(fminf(uv.x * float(kStarMapSide), float(kStarMapSide - 1)));
    const uint32_t cy = uint32_t(fminf(uv.y * float(kStarMapSide), float(kStarMapSide - 1)));
    const Star star = starInCell(cx, cy);
    if (!star.present) return {};
    const float radius = kStarDiskRadius / float(kStarMapSide), dx = uv.x - star.centre.x, dy = uv.y - star.centre.y;
    if (dx * dx + dy * dy > radius * radius) return {};
    const float solidAngle = kPi * radius * radius * 4.0f * kPi;  // the map's area times 4 pi
    return star.colour * (starIrradiance(stars.magnitudeZeroIrradiance, star.magnitude) / solidAngle);
}

/// Radiance of the night sky's stars along the unit world direction `dir` (y up), added to the
/// sky's on a miss. The sky's importance table leaves them out: BSDF sampling alone finds them.
URBIS_HD inline Vec3f nightSkyRadiance(const StarField& stars, Vec3f dir) {
    if (!(stars.magnitudeZeroIrradiance > 0.0f)) return {};
    const Vec3f c{dot(stars.celestialFromWorld[0], dir), dot(stars.celestialFromWorld[1], dir), dot(stars.celestialFromWorld[2], dir)};
    return starRadianceAt(stars, equalAreaSquareFromSphere(c));
}

} // namespace urbis
