// Counter-based random numbers: a value is a pure function of (seed, pixel, sample, dimension),
// so an image does not depend on how pixels are spread over threads or devices.
#pragma once

#include "urbis.h"

#include <cstdint>

namespace urbis {

/// 32-bit avalanche mix (the "lowbias32" finaliser of C. Wellons' hash prospector).
URBIS_HD inline uint32_t mixBits(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/// Hash of four words; each word goes through a full mix so nearby counters decorrelate.
URBIS_HD inline uint32_t hash4(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    uint32_t h = mixBits(a + 0x9e3779b9U);
    h = mixBits(h ^ (b + 0x85ebca6bU));
    h = mixBits(h ^ (c + 0xc2b2ae35U));
    return mixBits(h ^ (d + 0x27d4eb2fU));
}

/// Maps 32 random bits to a float in [0, 1).
URBIS_HD inline float bitsToUnitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

/// The sample stream of one pixel sample: draw() returns the next dimension.
struct SampleStream {
    uint32_t seed, pixel, sample, dimension = 0;

    URBIS_HD float draw() { return bitsToUnitFloat(hash4(seed, pixel, sample, dimension++)); }
};

} // namespace urbis
