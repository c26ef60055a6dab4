// A stored triangle: the geometry record of the triangle representation (host+device POD).
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// Three vertices in world space (metres).
struct Triangle {
    Vec3f p0, p1, p2;
};

/// What a triangle belongs to: its material and the object (building, road, ground) it is part of.
struct TriangleInfo {
    uint32_t material = 0;
    uint32_t object = 0;
};

} // namespace urbis
