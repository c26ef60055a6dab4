#include "bvh4/build.h"

#include "accel/binary_bvh.h"

#include <cfloat>

namespace urbis {
namespace {

BvhNode emptyNode() {
    BvhNode node;
    for (int l = 0; l < kBvhWidth; ++l) {
        for (int axis = 0; axis < 3; ++axis) {
            node.bounds[axis][l] = FLT_MAX;
            node.bounds[axis + 3][l] = -FLT_MAX;
        }
        node.child[l] = 0;
        node.primCount[l] = 0;
    }
    return node;
}

/// Collapses the binary tree into 4-wide nodes (gatherLanes). Depth first, so siblings'
/// subtrees stay close in memory.
std::vector<BvhNode> collapse(const std::vector<BinaryNode>& binary) {
    // Counted first, so that the array is allocated once at its size (growing held up to three times it).
    size_t nodeCount = 1;
    collapseDepthFirst<kBvhWidth>(binary, kBvhWidth, [&](uint32_t, const uint32_t* lanes, int laneCount, uint32_t* children) {
        for (int l = 0; l < laneCount; ++l)
            if (!binary[lanes[l]].isLeaf()) children[l] = uint32_t(nodeCount++);
    });
    std::vector<BvhNode> wide;
    wide.reserve(nodeCount);
    wide.push_back(emptyNode());
    collapseDepthFirst<kBvhWidth>(binary, kBvhWidth, [&](uint32_t at, const uint32_t* lanes, int count, uint32_t* children) {
        for (int l = 0; l < count; ++l) {
            const BinaryNode& n = binary[lanes[l]];
            if (!n.isLeaf()) {
                children[l] = static_cast<uint32_t>(wide.size());
                wide.push_back(emptyNode());
            }
            BvhNode& w = wide[at];
            for (int axis = 0; axis < 3; ++axis) {
                w.bounds[axis][l] = n.box.lo[axis];
                w.bounds[axis + 3][l] = n.box.hi[axis];
            }
            w.child[l] = n.isLeaf() ? n.first : children[l];
            w.primCount[l] = n.primCount;
        }
    });
    return wide;
}

} // namespace

Bvh buildBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options,
             const std::vector<uint32_t>& primCosts) {
    Bvh bvh;
    if (primBounds.empty()) {
        bvh.nodes.push_back(emptyNode());
        return bvh;
    }
    BinaryBvh binary = buildBinaryBvh(primBounds, options, primCosts);
    bvh.primOrder = std::move(binary.primOrder);
    bvh.nodes = collapse(binary.nodes);
    return bvh;
}

float sahCost(const Bvh& bvh, const BvhBuildOptions& options) {
    Bounds3f root;
    for (int l = 0; l < kBvhWidth; ++l) root.extend(bvh.nodes[0].box(l));
    const float rootArea = root.area();
    if (rootArea <= 0.0f) return 0.0f;
    double cost = options.traversalCost;
    for (const BvhNode& node : bvh.nodes)
        for (int l = 0; l < kBvhWidth; ++l) {
            const double relArea = node.box(l).area() / rootArea;
            if (node.primCount[l] > 0)
                cost += relArea * options.intersectionCost * node.primCount[l];
            else if (!node.box(l).empty())
                cost += relArea * options.traversalCost;
        }
    return static_cast<float>(cost);
}

} // namespace urbis
