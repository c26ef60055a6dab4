// Binned SAH construction of a 4-wide BVH over primitive bounds (host).
#pragma once

#include "accel/bvh_node.h"
#include "math/bounds.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Knobs of the binned SAH builder. Costs are relative: only their ratio matters.
struct BvhBuildOptions {
    uint32_t binCount = 32;            ///< SAH bins per axis, 2..32
    uint32_t maxLeafSize = 8;          ///< a node with more primitives is always split
    float traversalCost = 1.0f;        ///< cost of visiting one interior node
    float intersectionCost = 1.0f;     ///< cost of testing one primitive
    /// Primitive cost units a leaf test takes at once (a TriangleBlock's four triangles): the SAH
    /// counts a leaf's cost in whole groups of this many units. 1: per primitive.
    uint32_t leafGroupSize = 1;
    uint32_t parallelThreshold = 8192; ///< nodes with fewer primitives are built by one task
};

/// A BVH: flat 4-wide nodes (nodes[0] is the root) and the primitive order of its leaves.
struct Bvh {
    std::vector<BvhNode> nodes;
    /// Leaves reference primitives [first, first+count) in primOrder order: callers reorder
    /// their arrays by primOrder (sorted[i] = original[primOrder[i]]).
    std::vector<uint32_t> primOrder;
};

/// Builds a BVH over primitive bounds in world space: a binary tree by binned SAH over all
/// three axes (I. Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies",
/// 2007), then collapsed into 4-wide nodes by opening the largest child first. Subtrees
/// are built in parallel with TBB; the result is the same for any thread count. The tree
/// stays under 64 levels (object-median splits from depth 32 on), so traversal stacks of
/// kBvhStackSize never overflow. An empty input gives one empty node that no ray hits.
/// `primCosts` weighs each primitive's intersection cost in units of intersectionCost (empty: 1
/// each); a primitive of cost above one (a procedural wall) gets a leaf of its own. Integers keep
/// the parallel build deterministic.
Bvh buildBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options = {},
             const std::vector<uint32_t>& primCosts = {});

/// The SAH cost of a built BVH: traversalCost per node visited and intersectionCost per
/// primitive tested, each weighted by its box's area relative to the root's.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

} // namespace urbis
