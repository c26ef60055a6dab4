// Small fixed-size vectors used by per-ray code (host+device) and by the host layers.
#pragma once

#include "urbis.h"

#include <cmath>
#include <cstdint>

namespace urbis {

struct Vec2f {
    float x = 0, y = 0;
};

struct Vec3f {
    float x = 0, y = 0, z = 0;

    URBIS_HD float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    URBIS_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

URBIS_HD inline Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
URBIS_HD inline Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
URBIS_HD inline Vec3f operator-(Vec3f a) { return {-a.x, -a.y, -a.z}; }
URBIS_HD inline Vec3f operator*(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
URBIS_HD inline Vec3f operator*(Vec3f a, float s) { return {a.x * s, a.y * s, a.z * s}; }
URBIS_HD inline Vec3f operator*(float s, Vec3f a) { return a * s; }
URBIS_HD inline Vec3f operator/(Vec3f a, float s) { return a * (1.0f / s); }
URBIS_HD inline Vec3f& operator+=(Vec3f& a, Vec3f b) { return a = a + b; }
URBIS_HD inline Vec3f& operator*=(Vec3f& a, Vec3f b) { return a = a * b; }
URBIS_HD inline Vec3f& operator*=(Vec3f& a, float s) { return a = a * s; }

URBIS_HD inline float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// dot(a, b) in the same order with every product and sum rounded apart (urbis.h's exact operations):
/// for code that decides hits.
URBIS_HD inline float exactDot(Vec3f a, Vec3f b) {
    return exactAdd(exactAdd(exactMul(a.x, b.x), exactMul(a.y, b.y)), exactMul(a.z, b.z));
}
URBIS_HD inline Vec3f cross(Vec3f a, Vec3f b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
URBIS_HD inline float length(Vec3f a) { return std::sqrt(dot(a, a)); }
URBIS_HD inline Vec3f normalize(Vec3f a) { return a / length(a); }
URBIS_HD inline Vec3f vmin(Vec3f a, Vec3f b) { return {fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z)}; }
URBIS_HD inline Vec3f vmax(Vec3f a, Vec3f b) { return {fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z)}; }
URBIS_HD inline float maxComponent(Vec3f a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
/// Index 0..2 of the largest absolute component.
URBIS_HD inline int maxAbsAxis(Vec3f a) {
    float x = fabsf(a.x), y = fabsf(a.y), z = fabsf(a.z);
    return x > y ? (x > z ? 0 : 2) : (y > z ? 1 : 2);
}
/// Luminance of a linear Rec.709 colour.
URBIS_HD inline float luminance(Vec3f c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

} // namespace urbis
