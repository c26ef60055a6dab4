// A stored triangle: the geometry record of the triangle representation (host+device POD).
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// Three vertices in world space (metres).
struct Triangle {
    Vec3f p0, p1, p2;
};

/// What a triangle belongs to: its material, the object (building, road, ground) it is part of, and
/// which part of that object (a SurfacePart) it is. 8 bytes: objects are limited to 2^24.
struct TriangleInfo {
    uint32_t material = 0;
    uint32_t object : 24 = 0;
    uint32_t part : 8 = 0;
};

static_assert(sizeof(TriangleInfo) == 8, "TriangleInfo is meant to be 8 bytes");

} // namespace urbis
