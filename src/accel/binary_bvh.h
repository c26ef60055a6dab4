// The binned-SAH binary tree that the wide BVHs are collapsed from (host).
#pragma once

#include "accel/bvh_build.h"
#include "math/bounds.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// A node of the binary tree. Interior: primCount == 0, its left child the next node and `first` its
/// right child. Leaf: primitives [first, first + primCount) of BinaryBvh::primOrder.
struct BinaryNode {
    Bounds3f box;
    uint32_t first = 0;
    uint32_t primCount = 0;
    bool isLeaf() const { return primCount != 0; }
};

/// A binary BVH laid out depth first (the builder's slots: each subtree's nodes together, the left
/// child after its parent); nodes[0] is the root.
struct BinaryBvh {
    std::vector<BinaryNode> nodes;
    std::vector<uint32_t> primOrder;
};

/// A binary tree over primitive bounds in world space (at least one primitive), by binned SAH over
/// all three axes (I. Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007).
/// Subtrees are built in parallel with TBB; the result is the same for any thread count. The tree
/// stays under 64 levels (object-median splits from depth 32 on). `primCosts` weighs each
/// primitive's intersection cost in units of options.intersectionCost (empty: 1 each); a primitive
/// of cost above one (a procedural wall) gets a leaf of its own. Integers keep the parallel build
/// deterministic.
BinaryBvh buildBinaryBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options,
                         const std::vector<uint32_t>& primCosts);

/// The lanes of a wide node that stands for binary node `top`: its two children, then, while there
/// are fewer than `maxLanes` (>= 2), the interior lane of largest area opened into its two children
/// (after Embree's BVH builders); a leaf `top` (a root) is its own single lane. Writes binary node
/// indices to lanes[0, count) and returns count.
int gatherLanes(const std::vector<BinaryNode>& binary, uint32_t top, uint32_t* lanes, int maxLanes);

/// Collapses the binary tree into wide nodes, depth first so that each subtree's nodes lie together:
/// for each wide node `at` (0, the root, gets at most rootLanes lanes), fill(uint32_t at, const
/// uint32_t* lanes, int count, uint32_t* children) writes it from binary nodes lanes[0, count)
/// (gatherLanes) and sets children[l], for each interior lane l, to the index of its child's node.
template <int Width, typename Fill>
void collapseDepthFirst(const std::vector<BinaryNode>& binary, int rootLanes, Fill&& fill) {
    struct Pending {
        uint32_t wide, binary;
    };
    std::vector<Pending> stack{{0, 0}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        uint32_t lanes[Width], children[Width];
        const int count = gatherLanes(binary, p.binary, lanes, p.wide == 0 ? rootLanes : Width);
        fill(p.wide, static_cast<const uint32_t*>(lanes), count, static_cast<uint32_t*>(children));
        for (int l = count - 1; l >= 0; --l)
            if (!binary[lanes[l]].isLeaf()) stack.push_back({children[l], lanes[l]});
    }
}

} // namespace urbis
