// A planet's heightfield (host+device): fBm of 2D value noise, triplanar-mapped over the planet-fixed
// position of the base sphere's point under a world point (the Cambridge work's terrain), and its
// signed altitude above the terrain, a function of Lipschitz constant PlanetRecord::lipschitz for
// the ray march (Hart 1996, "Sphere tracing"). Camera-relative: each octave's lattice coordinate is
// the host's split of the camera's point (integer cell, fraction) plus the float offset from it.
#pragma once

#include "math/hash.h"
#include "scene/planet_record.h"

namespace urbis {

/// Quintic fade 6t^5 - 15t^4 + 10t^3 (Perlin 2002): its slope is at most 15/8.
URBIS_HD inline float planetFade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

/// Value noise in [-1, 1] at cell (cx, cy) + (fx, fy), fractions in [0, 1]: |grad| <= 15/8 x 2 x sqrt 2
/// per lattice unit (kValueNoiseSlope).
URBIS_HD inline float valueNoise2(uint32_t seed, uint32_t cx, uint32_t cy, float fx, float fy) {
    const auto v = [&](uint32_t x, uint32_t y) { return hashToUnit(hash3(seed, x, y)) * 2.0f - 1.0f; };
    const float sx = planetFade(fx), sy = planetFade(fy);
    const float a = v(cx, cy) + (v(cx + 1u, cy) - v(cx, cy)) * sx;
    const float b = v(cx, cy + 1u) + (v(cx + 1u, cy + 1u) - v(cx, cy + 1u)) * sx;
    return a + (b - a) * sy;
}
/// Bound of |grad valueNoise2| per lattice unit.
inline constexpr float kValueNoiseSlope = 1.875f * 2.0f * 1.41421356f;


/// The planet-fixed noise coordinate of octave `i` along axis `a` at offset `o` (metres, planet frame)
/// from the camera's point: integer cell (modulo 2^32) and fraction.
URBIS_HD inline void planetLattice(const PlanetRecord& pl, uint32_t i, int a, float o, float frequency, uint32_t& cell,
                                   float& frac) {
    const float x = pl.frac[i][a] + o * frequency;
    const float fl = floorf(x);
    cell = uint32_t(pl.cell[i][a]) + uint32_t(int32_t(fl));
    frac = x - fl;
}

/// Terrain height (metres above the base sphere, |h| <= amplitude) under the world point `p`:
/// sum over octaves i of gain^i x noise at frequency baseFrequency 2^i, each the triplanar blend of
/// three 2D noises of the planet-fixed coordinates, scaled to the amplitude. Octaves shorter than
/// 2 lodAngle |p| (two pixels at |p| from the camera) fade out over one octave, so that far terrain
/// costs fewer octaves; the fade depends on the point alone, so every ray sees the same surface.
/// `zenith`: the unit planet-fixed direction of p from the centre.
URBIS_HD inline float planetHeight(const PlanetRecord& pl, Vec3f p, Vec3f& zenith) {
    float toCentre;
    const float delta = radialOffset(pl, p, toCentre);
    // The base sphere's point under p, less the camera's, without cancellation: R (p - delta up) / |p - c|.
    const Vec3f s = (p - pl.up * delta) * (pl.radius / toCentre);
    const Vec3f q = (p + pl.up * pl.centreDistance) * (1.0f / toCentre);
    Vec3f o, n;
    for (int a = 0; a < 3; ++a) {
        o[a] = dot(pl.planetFromWorld[a], s);
        n[a] = dot(pl.planetFromWorld[a], q);
    }
    zenith = n;
    const Vec3f w = triplanarWeights(n);
    // Octaves kept in full: log2 of (octave 0's wavelength / (2 lodAngle d)); the next one fades.
    const float d = length(p);
    const float full = pl.lodAngle > 0.0f && d > 0.0f ? log2f(1.0f / (pl.baseFrequency * 2.0f * pl.lodAngle * d)) : 1e30f;
    float sum = 0.0f, amplitude = 1.0f, frequency = pl.baseFrequency;
    for (uint32_t i = 0; i < pl.octaves; ++i, amplitude *= pl.gain, frequency *= 2.0f) {
        const float keep = fminf(fmaxf(full - float(i) + 1.0f, 0.0f), 1.0f);
        if (keep <= 0.0f) break;  // and every finer octave
        float octave = 0.0f;
        for (int k = 0; k < 3; ++k) {
            if (w[k] <= 0.0f) continue;
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            uint32_t ca, cb;
            float fa, fb;
            planetLattice(pl, i, a, o[a], frequency, ca, fa);
            planetLattice(pl, i, b, o[b], frequency, cb, fb);
            octave += w[k] * valueNoise2(hash2(pl.seed, i * 3u + uint32_t(k)), ca, cb, fa, fb);
        }
        sum += amplitude * keep * octave;
    }
    return pl.heightScale * sum;
}

/// Signed altitude (metres) of the world point `p` above the terrain: positive above it. |grad| <=
/// pl.lipschitz, so a sphere of radius f / lipschitz around p holds no terrain.
URBIS_HD inline float planetTerrainDistance(const PlanetRecord& pl, Vec3f p) {
    Vec3f zenith;
    return planetAltitude(pl, p) - planetHeight(pl, p, zenith);
}

} // namespace urbis
