// Construction of the 8-wide compressed BVH by collapsing the binned-SAH binary tree (host).
#pragma once

#include "accel/bvh_build.h"
#include "accel/wide_bvh_node.h"
#include "math/bounds.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// An 8-wide compressed BVH: nodes (nodes[0] is the root) and the primitive order of its leaves.
struct WideBvh {
    std::vector<WideBvhNode> nodes;
    /// Leaves reference positions in primOrder: callers reorder their arrays by it (sorted[i] =
    /// original[primOrder[i]]).
    std::vector<uint32_t> primOrder;
};

/// Builds an 8-wide compressed BVH over primitive bounds in world space: buildBinaryBvh's binary tree
/// (binned SAH, whose leaves weigh `primCosts` as there, a costly primitive alone in its leaf, marked
/// kWideCostlyLeaf), collapsed by collapseDepthFirst (the interior lane of largest area opened until
/// there are kWideBvhWidth lanes); then each child box is quantised conservatively
/// against its node's box (WideBvhNode). Deterministic for any thread count. The tree keeps the
/// binary tree's depth bound (under 64 levels). Leaves hold at most 15 primitives (maxLeafSize is
/// capped there). An empty input gives one empty node.
WideBvh buildWideBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options = {},
                     const std::vector<uint32_t>& primCosts = {});

/// Hangs primitives `prims` (of world bounds `bounds`) from new roots above the tree, each a leaf of its
/// own at positions primOrder.size() on: a new root holds the old one as its interior child (every
/// node then moves up by one) and up to kWideBvhWidth - 1 of them. For primitives far larger than the
/// rest (the ground): built into the tree, their boxes would widen every node above their leaves,
/// which every ray would then visit.
void attachLeavesAtRoot(WideBvh& bvh, const std::vector<uint32_t>& prims, const std::vector<Bounds3f>& bounds);

/// The world box that lane `lane` of `node` decodes to (empty for an unused lane).
Bounds3f decodedBox(const WideBvhNode& node, int lane);

} // namespace urbis
