// A wide BVH's leaves regrouped into fixed-size groups of primitives (host): what SIMD leaf tests take.
#pragma once

#include "accel/wide_bvh_build.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Consecutive primitives of one leaf: positions [first, first + count) in the WideBvh's primOrder.
struct WideLeafGroup {
    uint32_t first;
    uint32_t count;   ///< 1..width
};

/// Splits every leaf of `bvh` into groups of at most `width` primitives (the last one short) and
/// makes the nodes address groups instead of primitives: a leaf lane's size (WideBvhNode::leafInfo)
/// becomes its group count, keeping the costly bit, and primBase the node's first group; the nodes'
/// groups follow one another in lane order, as their primitives did. Returns the groups, in primOrder.
/// traverseWideBvh then hands its primitive callback a group index. `width` 1..15; a tree built with
/// BvhBuildOptions::leafGroupSize = width has leaves that fill their groups.
std::vector<WideLeafGroup> groupWideLeaves(WideBvh& bvh, uint32_t width);

} // namespace urbis
