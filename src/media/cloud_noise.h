// Tileable noise for clouds (host+device): Perlin's gradient noise and Worley's cellular noise on an
// integer lattice that wraps with a period, and their fBm. buildClouds (media/cloud_build.cpp)
// evaluates them once per texel of the cloud noise volume and coverage field; per-ray code reads
// those tables. Perlin, "Improving Noise" (SIGGRAPH 2002); Worley, "A Cellular Texture Basis
// Function" (SIGGRAPH 1996); their Perlin-Worley blend after Schneider, "The Real-time Volumetric
// Cloudscapes of Horizon: Zero Dawn" (SIGGRAPH 2015 course).
#pragma once

#include "math/hash.h"
#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// x mod period for any integer x, in [0, period).
URBIS_HD inline int32_t wrapLattice(int32_t x, int32_t period) {
    const int32_t m = x % period;
    return m < 0 ? m + period : m;
}

/// Hash of a lattice point (already wrapped) and a seed.
URBIS_HD inline uint32_t latticeHash(uint32_t seed, int32_t x, int32_t y, int32_t z) {
    return hash2(hash3(seed, uint32_t(x), uint32_t(y)), uint32_t(z));
}

/// Perlin's quintic fade 6t^5 - 15t^4 + 10t^3.
URBIS_HD inline float perlinFade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

/// Dot product of the gradient that `h` picks among Perlin's 12 cube-edge directions with (x, y, z).
URBIS_HD inline float perlinGradient(uint32_t h, float x, float y, float z) {
    switch (h % 12u) {
    case 0: return x + y;
    case 1: return -x + y;
    case 2: return x - y;
    case 3: return -x - y;
    case 4: return x + z;
    case 5: return -x + z;
    case 6: return x - z;
    case 7: return -x - z;
    case 8: return y + z;
    case 9: return -y + z;
    case 10: return y - z;
    default: return -y - z;
    }
}

/// Perlin's gradient noise at `p` (lattice units), tiling with `period` lattice cells on every axis;
/// about [-1, 1] (exactly 0 at lattice points).
URBIS_HD inline float tiledPerlin(Vec3f p, int32_t period, uint32_t seed) {
    const float fx = floorf(p.x), fy = floorf(p.y), fz = floorf(p.z);
    const float x = p.x - fx, y = p.y - fy, z = p.z - fz;
    const int32_t ix = int32_t(fx), iy = int32_t(fy), iz = int32_t(fz);
    float corner[8];
    for (int c = 0; c < 8; ++c) {
        const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        const uint32_t h = latticeHash(seed, wrapLattice(ix + dx, period), wrapLattice(iy + dy, period),
                                       wrapLattice(iz + dz, period));
        corner[c] = perlinGradient(h, x - float(dx), y - float(dy), z - float(dz));
    }
    const float u = perlinFade(x), v = perlinFade(y), w = perlinFade(z);
    float edge[4];
    for (int e = 0; e < 4; ++e) edge[e] = corner[2 * e] + u * (corner[2 * e + 1] - corner[2 * e]);
    const float face0 = edge[0] + v * (edge[1] - edge[0]), face1 = edge[2] + v * (edge[3] - edge[2]);
    return face0 + w * (face1 - face0);
}

/// Worley's cellular noise at `p` (lattice units): the distance to the nearest of one feature point
/// per cell, inverted and clamped to [0, 1] (1 on a feature point), tiling with `period` cells.
URBIS_HD inline float tiledWorley(Vec3f p, int32_t period, uint32_t seed) {
    const float fx = floorf(p.x), fy = floorf(p.y), fz = floorf(p.z);
    const int32_t ix = int32_t(fx), iy = int32_t(fy), iz = int32_t(fz);
    float nearest2 = 3.0f;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const uint32_t h = latticeHash(seed, wrapLattice(ix + dx, period), wrapLattice(iy + dy, period),
                                               wrapLattice(iz + dz, period));
                const Vec3f feature{fx + float(dx) + hashToUnit(h), fy + float(dy) + hashToUnit(pcgHash(h)),
                                    fz + float(dz) + hashToUnit(pcgHash(h + 1u))};
                const Vec3f d = feature - p;
                nearest2 = fminf(nearest2, dot(d, d));
            }
    return fmaxf(0.0f, 1.0f - sqrtf(nearest2));
}

/// fBm of Perlin noise: `octaves` octaves from `period` lattice cells over the tile (each octave twice
/// the frequency, half the amplitude), mapped to about [0, 1]. `p` is in tile units ([0, 1) tiles).
URBIS_HD inline float tiledPerlinFbm(Vec3f p, int32_t period, uint32_t octaves, uint32_t seed) {
    float sum = 0, amplitude = 0.5f, norm = 0;
    for (uint32_t o = 0; o < octaves; ++o, period *= 2, amplitude *= 0.5f) {
        sum += amplitude * tiledPerlin(p * float(period), period, hash2(seed, o));
        norm += amplitude;
    }
    return fminf(1.0f, fmaxf(0.0f, 0.5f + 0.5f * sum / norm * 1.4f));   // 1.4: fBm rarely reaches its bound
}

/// fBm of Worley noise, as tiledPerlinFbm; in [0, 1].
URBIS_HD inline float tiledWorleyFbm(Vec3f p, int32_t period, uint32_t octaves, uint32_t seed) {
    float sum = 0, amplitude = 0.5f, norm = 0;
    for (uint32_t o = 0; o < octaves; ++o, period *= 2, amplitude *= 0.5f) {
        sum += amplitude * tiledWorley(p * float(period), period, hash2(seed, o + 16u));
        norm += amplitude;
    }
    return sum / norm;
}

} // namespace urbis
