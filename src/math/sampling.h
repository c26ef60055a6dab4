// Direction samplers, each beside its pdf (solid angle measure, about +z). Plain math: nvcc
// contracts and approximates it as it does all shading code. Each has a chi-square test
// (tests/sampling_chi2_test.cpp).
#pragma once

#include "math/constants.h"
#include "math/vec.h"

namespace urbis {

/// Cosine-weighted direction about +z from two uniform numbers (Malley's method over Shirley and
/// Chiu's concentric disk map).
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

/// A direction at polar cosine `cosTheta` about +z and azimuth 2 pi u.
URBIS_HD inline Vec3f directionAtCosine(float cosTheta, float u) {
    float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u;
    return {sinTheta * cosf(phi), sinTheta * sinf(phi), cosTheta};
}

/// Uniform direction inside the cone of half-angle acos(cosMax) about +z.
URBIS_HD inline Vec3f sampleUniformCone(float u1, float u2, float cosMax) {
    return directionAtCosine(1.0f - u1 * (1.0f - cosMax), u2);
}
URBIS_HD inline float uniformConePdf(float cosMax) { return 1.0f / (2.0f * kPi * (1.0f - cosMax)); }

/// Uniform direction over the whole sphere.
URBIS_HD inline Vec3f sampleUniformSphere(float u1, float u2) { return directionAtCosine(1.0f - 2.0f * u1, u2); }
URBIS_HD inline float uniformSpherePdf() { return 1.0f / (4.0f * kPi); }

/// Direction about +z distributed as the normalised Phong lobe (n + 1) / (2 pi) cos^n(theta).
URBIS_HD inline Vec3f samplePhongLobe(float u1, float u2, float exponent) {
    return directionAtCosine(powf(u1, 1.0f / (exponent + 1.0f)), u2);
}
URBIS_HD inline float phongLobePdf(float cosTheta, float exponent) {
    return cosTheta > 0.0f ? (exponent + 1.0f) / (2.0f * kPi) * powf(cosTheta, exponent) : 0.0f;
}

/// Uniform point on a triangle from two uniform numbers, as the barycentric weights (x of p1, y of
/// p2) of p = p0 + x (p1 - p0) + y (p2 - p0): the square-root parameterisation (Shirley 1997).
URBIS_HD inline Vec2f sampleUniformTriangle(float u1, float u2) {
    float s = sqrtf(u1);
    return {u2 * s, (1.0f - u2) * s};
}

} // namespace urbis
