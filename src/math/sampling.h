// Direction samplers, each beside its pdf (solid angle measure).
#pragma once

#include "math/vec.h"

namespace urbis {

constexpr float kPi = 3.14159265358979323846f;

/// Cosine-weighted direction about +z from two uniform numbers (Malley's method, concentric disk).
URBIS_HD inline Vec3f sampleCosineHemisphere(float u1, float u2) {
    float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    float r, phi;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};
    if (a * a > b * b) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = kPi / 2.0f - (kPi / 4.0f) * (a / b);
    }
    float x = r * cosf(phi), y = r * sinf(phi);
    return {x, y, sqrtf(fmaxf(0.0f, 1.0f - x * x - y * y))};
}
URBIS_HD inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta / kPi : 0.0f; }

/// Uniform direction inside the cone of half-angle acos(cosMax) about +z.
URBIS_HD inline Vec3f sampleUniformCone(float u1, float u2, float cosMax) {
    float cosTheta = 1.0f - u1 * (1.0f - cosMax);
    float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u2;
    return {sinTheta * cosf(phi), sinTheta * sinf(phi), cosTheta};
}
URBIS_HD inline float uniformConePdf(float cosMax) { return 1.0f / (2.0f * kPi * (1.0f - cosMax)); }

/// Direction about +z distributed as the normalised Phong lobe (n + 1) / (2 pi) cos^n(theta).
URBIS_HD inline Vec3f samplePhongLobe(float u1, float u2, float exponent) {
    float cosTheta = powf(u1, 1.0f / (exponent + 1.0f));
    float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u2;
    return {sinTheta * cosf(phi), sinTheta * sinf(phi), cosTheta};
}
URBIS_HD inline float phongLobePdf(float cosTheta, float exponent) {
    return cosTheta > 0.0f ? (exponent + 1.0f) / (2.0f * kPi) * powf(cosTheta, exponent) : 0.0f;
}

} // namespace urbis
