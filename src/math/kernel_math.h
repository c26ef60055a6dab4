// sin, cos and pow for per-ray code (host+device). On the GPU they avoid the general library
// routines, whose handling of arguments that never occur here (huge angles, negative bases) made
// up some 1,100 instructions of the path-tracing kernel, whose size is what limits it
// (docs/gpu_notes.md). The CPU keeps sinf, cosf and powf, so its images do not change.
#pragma once

#include "math/vec.h"

#include <cmath>

namespace urbis {

constexpr float kPi = 3.14159265358979323846f;

/// sin and cos of an angle within [-pi, 2 pi]; on the GPU through sincospif, which needs no
/// reduction of huge arguments.
URBIS_HD inline void sinCos(float angle, float& s, float& c) {
#if defined(__CUDA_ARCH__)
    sincospif(angle * (1.0f / kPi), &s, &c);
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

} // namespace urbis
