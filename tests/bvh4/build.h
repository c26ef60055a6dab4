// Construction of the flat 4-wide BVH by collapsing the binned-SAH binary tree (host): the reference
// that the tests and urbis_bench compare the renderer's 8-wide BVH (src/accel/wide_bvh_build.h) with.
#pragma once

#include "accel/bvh_build.h"
#include "bvh4/node.h"
#include "math/bounds.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// A BVH: flat 4-wide nodes (nodes[0] is the root) and the primitive order of its leaves.
struct Bvh {
    std::vector<BvhNode> nodes;
    /// Leaves reference primitives [first, first+count) in primOrder order: callers reorder
    /// their arrays by primOrder (sorted[i] = original[primOrder[i]]).
    std::vector<uint32_t> primOrder;
};

/// Builds a BVH over primitive bounds in world space: buildBinaryBvh's binary tree (binned SAH,
/// deterministic for any thread count, under 64 levels, a primitive of cost above one alone in its
/// leaf), collapsed into 4-wide nodes by opening the largest child first (collapseDepthFirst), so
/// that traversal stacks of kBvhStackSize never overflow. An empty input gives one empty node that
/// no ray hits.
Bvh buildBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options = {},
             const std::vector<uint32_t>& primCosts = {});

/// The SAH cost of a built BVH: traversalCost per node visited and intersectionCost per
/// primitive tested, each weighted by its box's area relative to the root's.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

} // namespace urbis
