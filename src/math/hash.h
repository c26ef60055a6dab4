// Counter-based hashing for reproducible randomness (host+device): a value depends only on
// (seed, keys), never on call order, so work can be split across threads or GPU lanes.
#pragma once

#include "urbis.h"

#include <cstdint>

namespace urbis {

/// One round of the PCG-RXS-M-XS permutation of 32-bit integers. See "Hash Functions for GPU
/// Rendering", Jarzynski and Olano, JCGT 2020.
URBIS_HD inline uint32_t pcgHash(uint32_t v) {
    uint32_t state = v * 747796405u + 2891336453u;
    uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Hash of a seed and one key.
URBIS_HD inline uint32_t hash2(uint32_t seed, uint32_t key) { return pcgHash(key ^ pcgHash(seed)); }

/// Hash of a seed and two keys.
URBIS_HD inline uint32_t hash3(uint32_t seed, uint32_t a, uint32_t b) { return hash2(hash2(seed, a), b); }

/// Maps a hash to a float uniformly distributed in [0, 1) (24 bits of it).
URBIS_HD inline float hashToUnit(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

/// A stream of random numbers keyed by a hash: the i-th draw is hash2(key, i).
struct HashStream {
    uint32_t key = 0;
    uint32_t counter = 0;

    /// Next raw 32-bit value.
    URBIS_HD uint32_t next() { return hash2(key, counter++); }
    /// Next float uniform in [0, 1).
    URBIS_HD float uniform() { return hashToUnit(next()); }
    /// Next float uniform in [lo, hi).
    URBIS_HD float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    /// Next float with (approximately) a standard normal distribution: the Irwin-Hall sum of
    /// four uniforms, rescaled to unit variance; tails are bounded at +-3.46.
    URBIS_HD float normal() { return (uniform() + uniform() + uniform() + uniform() - 2.0f) * 1.7320508f; }
};

} // namespace urbis
