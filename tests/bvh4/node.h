// The node of the flat 4-wide BVH (host+device POD): the reference that the tests and urbis_bench
// compare the renderer's 8-wide BVH (src/accel/wide_bvh_node.h) with.
#pragma once

#include "math/bounds.h"

#include <cstdint>

namespace urbis {

/// Children per node.
inline constexpr int kBvhWidth = 4;

/// One node of a 4-wide BVH in a flat array: 128 bytes, two CPU cache lines or one GPU L1
/// line. Lanes are stored structure-of-arrays (bounds[plane][lane]) so that the four slab
/// tests are one loop the compiler turns into SIMD on the CPU.
/// Lane l is
///   - an interior child if primCount[l] == 0 and its bounds are not empty: nodes[child[l]];
///   - a leaf if primCount[l] > 0: primitives [child[l], child[l] + primCount[l]) of the
///     build's primOrder;
///   - unused if its bounds are empty (lo = +FLT_MAX, hi = -FLT_MAX), which no ray hits.
/// nodes[0] is the root.
struct alignas(64) BvhNode {
    float bounds[6][kBvhWidth];       ///< lo.x, lo.y, lo.z, hi.x, hi.y, hi.z per lane; world space, metres
    uint32_t child[kBvhWidth];
    uint32_t primCount[kBvhWidth];    ///< primitives in the leaf; 0 if not a leaf

    URBIS_HD Bounds3f box(int lane) const {
        return {{bounds[0][lane], bounds[1][lane], bounds[2][lane]}, {bounds[3][lane], bounds[4][lane], bounds[5][lane]}};
    }
};

static_assert(sizeof(BvhNode) == 128, "BvhNode is meant to be 128 bytes");

} // namespace urbis
