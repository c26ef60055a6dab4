// A stored triangle: the record of the triangle kind (host+device POD), its bounds and BVH cost.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// Three vertices in world space (metres).
struct Triangle {
    Vec3f p0, p1, p2;

    /// Cost of testing one, in triangles (the BVH's surface area heuristic); 1: leaves share it.
    static constexpr uint32_t kBvhCost = 1;
};

/// World bounds of a triangle.
inline Bounds3f primBounds(const Triangle& t) {
    Bounds3f b;
    b.extend(t.p0);
    b.extend(t.p1);
    b.extend(t.p2);
    return b;
}

/// What a triangle belongs to: its material, the object (building, road, ground) it is part of, and
/// which part of that object (a SurfacePart) it is. 8 bytes: objects are limited to 2^24.
struct TriangleInfo {
    uint32_t material = 0;
    uint32_t object : 24 = 0;
    uint32_t part : 8 = 0;
};

static_assert(sizeof(TriangleInfo) == 8, "TriangleInfo is meant to be 8 bytes");

} // namespace urbis
