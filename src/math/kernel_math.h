// Shading helpers left from before the precision policy (urbis.h): plain math now, which the GPU
// build contracts and approximates by itself. New code writes the plain expressions instead; these
// go once no caller is left.
#pragma once

#include "math/vec.h"

#include <cmath>

namespace urbis {

constexpr float kPi = 3.14159265358979323846f;

/// sin and cos of an angle.
URBIS_HD inline void sinCos(float angle, float& s, float& c) {
    s = sinf(angle);
    c = cosf(angle);
}

/// x^y for x >= 0.
URBIS_HD inline float powPositive(float x, float y) { return powf(x, y); }

/// a / b.
URBIS_HD inline float approxDivide(float a, float b) { return a / b; }

/// sqrt(x) for x >= 0.
URBIS_HD inline float approxSqrt(float x) { return sqrtf(x); }

/// a * b + c.
URBIS_HD inline float fusedMulAdd(float a, float b, float c) { return a * b + c; }
URBIS_HD inline Vec3f fusedMulAdd(Vec3f a, Vec3f b, Vec3f c) { return a * b + c; }
URBIS_HD inline Vec3f fusedMulAdd(Vec3f a, float b, Vec3f c) { return a * b + c; }

/// dot(a, b).
URBIS_HD inline float fusedDot(Vec3f a, Vec3f b) { return dot(a, b); }

/// v / |v|.
URBIS_HD inline Vec3f approxNormalize(Vec3f v) { return normalize(v); }

} // namespace urbis
