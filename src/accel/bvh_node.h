// The flat binary BVH node that the CPU and the GPU read as it is (host+device POD).
#pragma once

#include "math/bounds.h"

#include <cstdint>

namespace urbis {

/// One node of a binary BVH in a flat array, 32 bytes (two per 64-byte cache line).
/// Interior node: primCount == 0, its children are nodes[first] and nodes[first + 1].
/// Leaf: primitives [first, first + primCount) of the build's primOrder.
/// Bounds are stored as lo.xyz, hi.xyz so that traversal can pick the near plane of each
/// axis by index from the ray's octant.
struct BvhNode {
    float bounds[6];   ///< lo.x, lo.y, lo.z, hi.x, hi.y, hi.z in world space, metres
    uint32_t first;
    uint32_t primCount;

    URBIS_HD bool isLeaf() const { return primCount != 0; }
    URBIS_HD Bounds3f box() const {
        return {{bounds[0], bounds[1], bounds[2]}, {bounds[3], bounds[4], bounds[5]}};
    }
};

static_assert(sizeof(BvhNode) == 32, "BvhNode is meant to be 32 bytes");

} // namespace urbis
