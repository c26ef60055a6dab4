// Direction samplers, each beside its pdf (solid angle measure).
#pragma once

#include "math/kernel_math.h"

namespace urbis {

/// Cosine-weighted direction about +z from two uniform numbers (Malley's method, concentric disk).
URBIS_HD inline Vec3f sampleCosineHemisphere(float u1, float u2) {
    float a = fusedMulAdd(2.0f, u1, -1.0f), b = fusedMulAdd(2.0f, u2, -1.0f);
    float r, phi;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};
    if (a * a > b * b) {
        r = a;
        phi = (kPi / 4.0f) * approxDivide(b, a);
    } else {
        r = b;
        phi = fusedMulAdd(-kPi / 4.0f, approxDivide(a, b), kPi / 2.0f);
    }
    float s, c;
    sinCos(phi, s, c);
    float x = r * c, y = r * s;
    return {x, y, approxSqrt(fmaxf(0.0f, fusedMulAdd(-y, y, fusedMulAdd(-x, x, 1.0f))))};
}
URBIS_HD inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? approxDivide(cosTheta, kPi) : 0.0f; }

/// Uniform direction inside the cone of half-angle acos(cosMax) about +z.
URBIS_HD inline Vec3f sampleUniformCone(float u1, float u2, float cosMax) {
    float cosTheta = fusedMulAdd(-u1, 1.0f - cosMax, 1.0f);
    float sinTheta = approxSqrt(fmaxf(0.0f, fusedMulAdd(-cosTheta, cosTheta, 1.0f)));
    float s, c;
    sinCos(2.0f * kPi * u2, s, c);
    return {sinTheta * c, sinTheta * s, cosTheta};
}
URBIS_HD inline float uniformConePdf(float cosMax) { return approxDivide(1.0f, 2.0f * kPi * (1.0f - cosMax)); }

/// Direction about +z distributed as the normalised Phong lobe (n + 1) / (2 pi) cos^n(theta).
URBIS_HD inline Vec3f samplePhongLobe(float u1, float u2, float exponent) {
    float cosTheta = powPositive(u1, approxDivide(1.0f, exponent + 1.0f));
    float sinTheta = approxSqrt(fmaxf(0.0f, fusedMulAdd(-cosTheta, cosTheta, 1.0f)));
    float s, c;
    sinCos(2.0f * kPi * u2, s, c);
    return {sinTheta * c, sinTheta * s, cosTheta};
}
URBIS_HD inline float phongLobePdf(float cosTheta, float exponent) {
    return cosTheta > 0.0f ? approxDivide(exponent + 1.0f, 2.0f * kPi) * powPositive(cosTheta, exponent) : 0.0f;
}

} // namespace urbis
