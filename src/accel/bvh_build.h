// Binned SAH construction of a binary BVH over primitive bounds (host).
#pragma once

#include "accel/bvh_node.h"
#include "math/bounds.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Knobs of the binned SAH builder. Costs are relative: only their ratio matters.
struct BvhBuildOptions {
    uint32_t binCount = 32;            ///< SAH bins per axis, 2..64
    uint32_t maxLeafSize = 8;          ///< a node with more primitives is always split
    float traversalCost = 1.0f;        ///< cost of visiting one interior node
    float intersectionCost = 1.0f;     ///< cost of testing one primitive
    uint32_t parallelThreshold = 8192; ///< nodes with fewer primitives are built by one task
};

/// A BVH: flat nodes (nodes[0] is the root) and the primitive order of its leaves.
struct Bvh {
    std::vector<BvhNode> nodes;
    /// Leaves reference primitives [first, first+count) in primOrder order: callers reorder
    /// their arrays by primOrder (sorted[i] = original[primOrder[i]]).
    std::vector<uint32_t> primOrder;
};

/// Builds a binary BVH by binned SAH (I. Wald, "On fast Construction of SAH-based Bounding
/// Volume Hierarchies", 2007) over primitive bounds in world space, trying every axis.
/// Subtrees are built in parallel with TBB; the result is the same for any thread count.
/// Depth is bounded (below 64) so that traversal stacks of kBvhStackSize never overflow.
/// An empty input gives a single empty leaf that no ray hits.
Bvh buildBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options = {});

/// The SAH cost of a built BVH, in units of options' costs, normalised by the root's area.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

} // namespace urbis
