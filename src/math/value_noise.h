// Value noise with analytic derivatives and the fBm terrain built of it (host+device). See Inigo
// Quilez, "Value noise derivatives" and "Terrain raymarching" (iquilezles.org, 2008): the quintic
// fade makes the noise C2, so its gradient is exact and continuous, and the erosion-like damping
// divides each octave by 1 + |sum of the gradients so far|^2, which flattens valleys and sharpens ridges.
#pragma once

#include "math/hash.h"
#include "math/vec.h"

#include <cmath>
#include <cstdint>

namespace urbis {

/// A noise value and its gradient (d/dx, d/dy) in the noise's own units.
struct NoiseSample {
    float value = 0;
    Vec2f gradient;
};

/// The lattice value at integer point (i, j): uniform in [-1, 1).
URBIS_HD inline float latticeValue(uint32_t seed, int32_t i, int32_t j) {
    return hashToUnit(hash3(seed, uint32_t(i), uint32_t(j))) * 2.0f - 1.0f;
}

/// 2D value noise at `p` with its analytic gradient: the lattice values blended by the quintic
/// fade 6f^5 - 15f^4 + 10f^3. Values in [-1, 1]; each partial derivative at most 15/8 * 2 in size.
URBIS_HD inline NoiseSample valueNoise(uint32_t seed, Vec2f p) {
    const float fx0 = floorf(p.x), fy0 = floorf(p.y);
    const int32_t i = int32_t(fx0), j = int32_t(fy0);
    const float fx = p.x - fx0, fy = p.y - fy0;
    const float ux = fx * fx * fx * (fx * (fx * 6.0f - 15.0f) + 10.0f);
    const float uy = fy * fy * fy * (fy * (fy * 6.0f - 15.0f) + 10.0f);
    const float dux = 30.0f * fx * fx * (fx * (fx - 2.0f) + 1.0f);
    const float duy = 30.0f * fy * fy * (fy * (fy - 2.0f) + 1.0f);
    const float a = latticeValue(seed, i, j), b = latticeValue(seed, i + 1, j);
    const float c = latticeValue(seed, i, j + 1), d = latticeValue(seed, i + 1, j + 1);
    const float k1 = b - a, k2 = c - a, k4 = a - b - c + d;
    return {a + k1 * ux + k2 * uy + k4 * ux * uy, {dux * (k1 + k4 * uy), duy * (k2 + k4 * ux)}};
}

/// The parameters of an fBm terrain, in metres (scene files: docs/scene_files.md § terrain).
struct FbmParams {
    uint32_t seed = 7;
    uint32_t octaves = 9;
    float wavelength = 1500.0f;   ///< of the first octave, metres
    float amplitude = 400.0f;     ///< metres: the first octave's noise (in [-1, 1]) times this
    float lacunarity = 2.0f;      ///< frequency ratio of successive octaves
    float gain = 0.5f;            ///< amplitude ratio of successive octaves
    float erosion = 1.0f;         ///< 0: plain fBm; 1: Quilez's full derivative damping
    float warp = 0.0f;            ///< domain distortion, metres: the offset the warp noise applies
    float offset = 150.0f;        ///< metres added to every height
};

/// The fBm sum at `p` (metres) without damping or warp: sum of amplitude * gain^i * noise(p * f_i),
/// with its exact gradient (metres per metre). The octaves are rotated by a fixed matrix so their
/// lattices do not line up.
URBIS_HD inline NoiseSample fbm(const FbmParams& f, Vec2f p) {
    float freq = 1.0f / f.wavelength, amp = f.amplitude;
    // Rotation by about 36.87 degrees (3-4-5), applied once per octave: q_i = R^i p * freq_i.
    float rx = 1.0f, ry = 0.0f;   // first row of R^i; the second is (-ry, rx)
    NoiseSample sum;
    for (uint32_t o = 0; o < f.octaves; ++o) {
        const Vec2f q{(rx * p.x + ry * p.y) * freq, (-ry * p.x + rx * p.y) * freq};
        const NoiseSample n = valueNoise(f.seed + o, q);
        sum.value += amp * n.value;
        // d n(R p f)/dp = f R^T grad n.
        sum.gradient.x += amp * freq * (rx * n.gradient.x - ry * n.gradient.y);
        sum.gradient.y += amp * freq * (ry * n.gradient.x + rx * n.gradient.y);
        const float nx = 0.8f * rx - 0.6f * ry, ny = 0.6f * rx + 0.8f * ry;
        rx = nx, ry = ny;
        freq *= f.lacunarity;
        amp *= f.gain;
    }
    return sum;
}

/// The terrain's height at `p` (metres): the domain warped by two low-frequency noises (Cambridge's
/// domain distortion), then the octaves each damped by 1 / (1 + erosion |g|^2), g the sum of the
/// gradients (per unit noise) of the octaves before it (Quilez), plus the offset.
URBIS_HD inline float fbmTerrainHeight(const FbmParams& f, Vec2f p) {
    if (f.warp != 0.0f) {
        const float s = 0.5f / f.wavelength;
        p.x += f.warp * valueNoise(f.seed + 101u, {p.x * s, p.y * s}).value;
        p.y += f.warp * valueNoise(f.seed + 202u, {p.x * s + 5.2f, p.y * s + 1.3f}).value;
    }
    float freq = 1.0f / f.wavelength, amp = f.amplitude, height = 0.0f;
    float rx = 1.0f, ry = 0.0f;
    Vec2f g;
    for (uint32_t o = 0; o < f.octaves; ++o) {
        const Vec2f q{(rx * p.x + ry * p.y) * freq, (-ry * p.x + rx * p.y) * freq};
        const NoiseSample n = valueNoise(f.seed + o, q);
        g.x += n.gradient.x;
        g.y += n.gradient.y;
        height += amp * n.value / (1.0f + f.erosion * (g.x * g.x + g.y * g.y));
        const float nx = 0.8f * rx - 0.6f * ry, ny = 0.6f * rx + 0.8f * ry;
        rx = nx, ry = ny;
        freq *= f.lacunarity;
        amp *= f.gain;
    }
    return height + f.offset;
}

/// The sum of the octaves' amplitudes (metres): |fbmTerrainHeight - offset| never exceeds it.
URBIS_HD inline float fbmAmplitudeBound(const FbmParams& f) {
    float amp = f.amplitude, sum = 0.0f;
    for (uint32_t o = 0; o < f.octaves; ++o, amp *= f.gain) sum += fabsf(amp);
    return sum;
}

} // namespace urbis
