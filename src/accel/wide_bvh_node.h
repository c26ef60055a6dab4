// The 8-wide compressed BVH node (host+device POD): 80 bytes with child boxes quantised to 8 bits.
#pragma once

#include "urbis.h"

#include <cstdint>

namespace urbis {

/// Children per wide node.
inline constexpr int kWideBvhWidth = 8;

/// WideBvhNode::leafInfo bit of a leaf that holds a primitive costlier than a triangle (a wall).
inline constexpr uint8_t kWideCostlyLeaf = 0x80;

/// One node of an 8-wide BVH with quantised child boxes, after Ylitie, Karras and Laine, "Efficient
/// Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG 2017 (section 3.1), and
/// Embree's compressed nodes. A child box is 8 bits per plane on a grid of the node: along axis a,
/// plane value q decodes to origin[a] + q * 2^(exponent[a] - 127) (decodePlane), rounded so that the
/// decoded box holds the child's true box (wide_bvh_build.cpp). Planes are stored structure of arrays
/// (q[plane][lane]) so that eight lanes decode and slab-test at once.
/// Lane l is
///   - an interior child if innerMask bit l is set: nodes[childBase + interior lanes below l];
///   - a leaf if leafInfo[l] & 15 is its primitive count (1..8): primitives from primBase + the
///     counts of the leaf lanes below l, in the build's primOrder; kWideCostlyLeaf marks a costly one;
///   - unused otherwise, with the empty box q lo = 255, q hi = 0, which no ray hits.
struct alignas(16) WideBvhNode {
    float origin[3];          ///< world space, metres: the grid's corner (the node box's lo)
    uint8_t exponent[3];      ///< the grid step per axis, as a float's biased exponent: 2^(e - 127)
    uint8_t innerMask;        ///< bit l: lane l is an interior child
    uint32_t childBase;       ///< the first interior child; the others follow in lane order
    uint32_t primBase;        ///< the first primitive of the node's leaves, which follow in lane order
    uint8_t leafInfo[kWideBvhWidth];   ///< primitive count of a leaf lane, or'ed with kWideCostlyLeaf; 0 otherwise
    uint8_t q[6][kWideBvhWidth];       ///< lo.x, lo.y, lo.z, hi.x, hi.y, hi.z per lane, quantised

    /// The grid step along `axis`: a power of two.
    URBIS_HD float step(int axis) const { return __builtin_bit_cast(float, uint32_t(exponent[axis]) << 23); }

    /// The world coordinate of quantised plane value `value` along `axis`. q * step is exact (8 bits
    /// times a power of two) and the sum is rounded once, the same on every backend and instruction set.
    URBIS_HD float decodePlane(int axis, uint32_t value) const {
        return exactAdd(origin[axis], exactMul(float(value), step(axis)));
    }

    URBIS_HD uint32_t leafSize(int lane) const { return leafInfo[lane] & 15u; }
    URBIS_HD bool costlyLeaf(int lane) const { return (leafInfo[lane] & kWideCostlyLeaf) != 0; }
};

static_assert(sizeof(WideBvhNode) == 80, "WideBvhNode is meant to be 80 bytes");

} // namespace urbis
