// Tests on the ground's plane (host): world x and z of points, segments and triangles, y ignored,
// for laying the city's surfaces onto the terrain's samples.
#pragma once

#include "scene/triangle.h"

#include <algorithm>
#include <cmath>

namespace urbis {

/// Distance (m) on the plane from (x, z) to the segment ab.
inline float planeSegmentDistance(float x, float z, Vec3f a, Vec3f b) {
    const float abx = b.x - a.x, abz = b.z - a.z, apx = x - a.x, apz = z - a.z;
    const float len2 = abx * abx + abz * abz;
    const float s = len2 > 0 ? std::clamp((apx * abx + apz * abz) / len2, 0.0f, 1.0f) : 0.0f;
    return std::hypot(apx - abx * s, apz - abz * s);
}

/// Whether (x, z) lies in triangle t's plane projection, its edges included.
inline bool insidePlaneTriangle(const Triangle& t, float x, float z) {
    auto side = [&](Vec3f a, Vec3f b) { return (b.x - a.x) * (z - a.z) - (b.z - a.z) * (x - a.x); };
    const float s0 = side(t.p0, t.p1), s1 = side(t.p1, t.p2), s2 = side(t.p2, t.p0);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

/// The samples (index first..last) of a grid from `origin`, `cell` metres apart, `n` of them, that lie
/// in [lo, hi]; false if none.
inline bool gridSamplesIn(float lo, float hi, float origin, float cell, uint32_t n, int& first, int& last) {
    first = std::max(0, int(std::ceil((lo - origin) / cell)));
    last = std::min(int(n) - 1, int(std::floor((hi - origin) / cell)));
    return first <= last;
}

} // namespace urbis
