// Shading math for per-ray code (host+device): sin, cos, pow, quotients, square roots and unit
// vectors of camera rays, sampled directions, normals, pdfs and weights. On the GPU they are the
// hardware's approximations: the library's exact routines handle arguments that never occur here
// (huge angles, negative bases, denormal quotients) with code that made the render kernel larger,
// and its size is what limits it (docs/gpu_notes.md, fourth and eighth sessions). The CPU keeps the
// exact routines, so its images do not change. Traversal and intersection do not use these: a
// given ray hits the same primitive at the same distance on both (tests/gpu_traversal_test.cpp);
// the rays a path makes differ by a few ulps, so the GPU's images agree with the CPU's within
// tests/gpu_render_test.cpp's tolerance.
#pragma once

#include "math/vec.h"

#include <cmath>

namespace urbis {

constexpr float kPi = 3.14159265358979323846f;

/// sin and cos of an angle within [-pi, 2 pi]; on the GPU through the hardware's approximation,
/// within 2^-21.4 of the true values on [-pi, pi] (CUDA C++ Programming Guide, intrinsic functions),
/// where the angle is brought first. sincospif took 110 instructions more, and every instruction
/// of the walls' render kernel costs it time (docs/gpu_notes.md, eighth session).
URBIS_HD inline void sinCos(float angle, float& s, float& c) {
#if defined(__CUDA_ARCH__)
    __sincosf(angle > kPi ? angle - 2.0f * kPi : angle, &s, &c);
#else
    s = sinf(angle);
    c = cosf(angle);
#endif
}

/// x^y for x >= 0 (cosines, uniform numbers); on the GPU exp2(y log2 x) with the hardware's
/// approximations (relative error about 2^-21 |y log2 x|: under 2e-4 for the Phong exponents
/// used; the GPU image still matches the CPU's, tests/gpu_render_test.cpp).
URBIS_HD inline float powPositive(float x, float y) {
#if defined(__CUDA_ARCH__)
    return __powf(x, y);
#else
    return powf(x, y);
#endif
}

/// a / b; on the GPU __fdividef (within 2 ulp for |b| < 2^126).
URBIS_HD inline float approxDivide(float a, float b) {
#if defined(__CUDA_ARCH__)
    return __fdividef(a, b);
#else
    return a / b;
#endif
}

/// sqrt(x) for x >= 0; on the GPU x / sqrt(x) by the hardware's reciprocal square root.
URBIS_HD inline float approxSqrt(float x) {
#if defined(__CUDA_ARCH__)
    return x > 0.0f ? x * rsqrtf(x) : 0.0f;
#else
    return sqrtf(x);
#endif
}

/// a * b + c; on the GPU one fused multiply-add, rounded once. The build keeps nvcc from fusing on its
/// own (-fmad=false), so that hits match the CPU's; the shading math fuses here, by name, which made
/// the walls' render kernel ~120 instructions smaller (docs/gpu_notes.md, ninth session).
URBIS_HD inline float fusedMulAdd(float a, float b, float c) {
#if defined(__CUDA_ARCH__)
    return __fmaf_rn(a, b, c);
#else
    return a * b + c;
#endif
}
URBIS_HD inline Vec3f fusedMulAdd(Vec3f a, Vec3f b, Vec3f c) {
    return {fusedMulAdd(a.x, b.x, c.x), fusedMulAdd(a.y, b.y, c.y), fusedMulAdd(a.z, b.z, c.z)};
}
URBIS_HD inline Vec3f fusedMulAdd(Vec3f a, float b, Vec3f c) { return fusedMulAdd(a, Vec3f{b, b, b}, c); }

/// dot(a, b) by fused multiply-adds; on the CPU the same sums as dot (x, then y, then z).
URBIS_HD inline float fusedDot(Vec3f a, Vec3f b) { return fusedMulAdd(a.z, b.z, fusedMulAdd(a.y, b.y, a.x * b.x)); }

/// v / |v|; on the GPU by the hardware's reciprocal square root.
URBIS_HD inline Vec3f approxNormalize(Vec3f v) {
#if defined(__CUDA_ARCH__)
    return v * rsqrtf(fusedDot(v, v));
#else
    return normalize(v);
#endif
}

} // namespace urbis
