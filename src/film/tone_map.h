// Exposure, filmic tone curve and sRGB encoding (host+device).
#pragma once

#include "math/vec.h"

namespace urbis {

/// ACES filmic curve fitted by K. Narkowicz (2015), applied per channel to linear radiance.
URBIS_HD inline float acesFilmic(float x) {
    float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return fminf(fmaxf(y, 0.0f), 1.0f);
}

/// sRGB transfer function (IEC 61966-2-1) for a value in [0, 1].
URBIS_HD inline float srgbEncode(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}

/// Linear radiance to an 8-bit sRGB value: scale by 2^exposure, filmic curve, encode, round.
URBIS_HD inline uint8_t toneMapChannel(float linear, float exposureScale) {
    float v = srgbEncode(acesFilmic(fmaxf(linear, 0.0f) * exposureScale));
    return uint8_t(v * 255.0f + 0.5f);
}

} // namespace urbis
