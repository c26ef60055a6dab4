#include "accel/wide_bvh_build.h"

#include "accel/binary_bvh.h"
#include "accel/wide_bvh_traverse.h"

#include <algorithm>
#include <cmath>

namespace urbis {
namespace {

/// A node whose lanes are all unused: no ray hits it.
WideBvhNode emptyNode() {
    WideBvhNode node{};
    for (int axis = 0; axis < 3; ++axis) {
        node.exponent[axis] = 127;
        for (int l = 0; l < kWideBvhWidth; ++l) {
            node.q[axis][l] = 255;
            node.q[axis + 3][l] = 0;
        }
    }
    return node;
}

/// Sets the node's grid from the union of its children's boxes and quantises each child's box onto
/// it conservatively: lo rounded down and hi up, checked against the very decode the traversal
/// makes (decodePlane), so the decoded box always holds the true one and no hit is lost.
void quantise(WideBvhNode& node, const Bounds3f (&boxes)[kWideBvhWidth], int count) {
    Bounds3f box;
    for (int l = 0; l < count; ++l) box.extend(boxes[l]);
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = box.lo[axis], hi = box.hi[axis];
        node.origin[axis] = lo;
        // The smallest power-of-two step whose 255 steps reach hi (a zero extent takes the smallest).
        int power = 0;
        const double need = (double(hi) - double(lo)) / 255.0;
        if (need > 0.0) std::frexp(need, &power);
        int biased = std::clamp(need > 0.0 ? power + 127 : 1, 1, 254);
        node.exponent[axis] = uint8_t(biased);
        while (biased < 254 && node.decodePlane(axis, 255) < hi) node.exponent[axis] = uint8_t(++biased);
        const double step = double(node.step(axis));
        for (int l = 0; l < count; ++l) {
            const float childLo = boxes[l].lo[axis], childHi = boxes[l].hi[axis];
            uint32_t qlo = uint32_t(std::clamp(std::floor((double(childLo) - lo) / step), 0.0, 255.0));
            uint32_t qhi = uint32_t(std::clamp(std::ceil((double(childHi) - lo) / step), 0.0, 255.0));
            while (qlo > 0 && node.decodePlane(axis, qlo) > childLo) --qlo;
            while (qhi < 255 && node.decodePlane(axis, qhi) < childHi) ++qhi;
            node.q[axis][l] = uint8_t(qlo);
            node.q[axis + 3][l] = uint8_t(qhi);
        }
    }
}

} // namespace

WideBvh buildWideBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options,
                     const std::vector<uint32_t>& primCosts) {
    WideBvh wide;
    wide.nodes.push_back(emptyNode());
    if (primBounds.empty()) return wide;
    BvhBuildOptions binaryOptions = options;
    binaryOptions.maxLeafSize = std::min(options.maxLeafSize, 15u);   // a leaf's count has four bits
    const BinaryBvh binary = buildBinaryBvh(primBounds, binaryOptions, primCosts);
    wide.primOrder.reserve(binary.primOrder.size());
    // A node's interior children are allocated together (childBase), its leaves' primitives likewise.
    collapseDepthFirst<kWideBvhWidth>(binary.nodes, kWideBvhWidth, [&](uint32_t at, const uint32_t* lanes, int count,
                                                                      uint32_t* children) {
        Bounds3f boxes[kWideBvhWidth];
        WideBvhNode node = emptyNode();
        node.childBase = uint32_t(wide.nodes.size());
        node.primBase = uint32_t(wide.primOrder.size());
        for (int l = 0; l < count; ++l) {
            const BinaryNode& n = binary.nodes[lanes[l]];
            boxes[l] = n.box;
            if (!n.isLeaf()) {
                children[l] = node.childBase + bitCount8(node.innerMask);
                node.innerMask |= uint8_t(1u << l);
                continue;
            }
            bool costly = false;
            for (uint32_t i = n.first; i < n.first + n.primCount; ++i) {
                wide.primOrder.push_back(binary.primOrder[i]);
                costly = costly || (!primCosts.empty() && primCosts[binary.primOrder[i]] > 1);
            }
            node.leafInfo[l] = uint8_t(n.primCount | (costly ? kWideCostlyLeaf : 0u));
        }
        quantise(node, boxes, count);
        wide.nodes[at] = node;
        wide.nodes.resize(wide.nodes.size() + bitCount8(node.innerMask));
    });
    return wide;
}

void attachLeavesAtRoot(WideBvh& bvh, const std::vector<uint32_t>& prims, const std::vector<Bounds3f>& bounds) {
    for (size_t first = 0; first < prims.size(); first += kWideBvhWidth - 1) {
        Bounds3f old;
        for (int l = 0; l < kWideBvhWidth; ++l) old.extend(decodedBox(bvh.nodes[0], l));
        WideBvhNode root = emptyNode();
        Bounds3f boxes[kWideBvhWidth];
        int count = 0;
        if (!old.empty()) {
            for (WideBvhNode& node : bvh.nodes) ++node.childBase;
            root.innerMask = 1;
            root.childBase = 1;
            boxes[count++] = old;
        }
        root.primBase = uint32_t(bvh.primOrder.size());
        for (size_t i = first; i < std::min(prims.size(), first + kWideBvhWidth - 1); ++i) {
            root.leafInfo[count] = 1;
            boxes[count++] = bounds[i];
            bvh.primOrder.push_back(prims[i]);
        }
        quantise(root, boxes, count);
        if (old.empty()) bvh.nodes[0] = root;
        else bvh.nodes.insert(bvh.nodes.begin(), root);
    }
}

Bounds3f decodedBox(const WideBvhNode& node, int lane) {
    Bounds3f box;
    if (!(node.innerMask >> lane & 1u) && node.leafSize(lane) == 0) return box;
    for (int axis = 0; axis < 3; ++axis) {
        box.lo[axis] = node.decodePlane(axis, node.q[axis][lane]);
        box.hi[axis] = node.decodePlane(axis, node.q[axis + 3][lane]);
    }
    return box;
}

} // namespace urbis
