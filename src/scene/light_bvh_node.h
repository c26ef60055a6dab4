// The light BVH's flat node array (host+device POD), as the GPU reads it: pbrt-v4's LightBVHNode
// and CompactLightBounds without the quantisation (a node is 52 bytes instead of 32; the few
// thousand to million nodes of a city's lights do not need the saving yet). Nodes are in depth-first
// order: an interior node's first child is the next node, its second at `child`.
#pragma once

#include "math/bounds.h"

namespace urbis {

struct LightBvhNode {
    Bounds3f bounds;       ///< world, metres
    Vec3f axis;            ///< unit: the cone of normals' axis
    float cosThetaO = 1;   ///< the cone of normals' half-angle
    float cosThetaE = 0;   ///< how far past a normal light leaves the surface
    float phi = 0;         ///< power of the lights below
    uint32_t packed = 0;   ///< bit 31: leaf; bit 30: two-sided; bits 0-29: second child (interior) or light (leaf)

    static constexpr uint32_t kLeafBit = 1u << 31, kTwoSidedBit = 1u << 30, kIndexMask = kTwoSidedBit - 1;
    URBIS_HD bool leaf() const { return (packed & kLeafBit) != 0; }
    URBIS_HD bool twoSided() const { return (packed & kTwoSidedBit) != 0; }
    /// An interior node's second child, or a leaf's light (index into SceneView::lightRecords).
    URBIS_HD uint32_t index() const { return packed & kIndexMask; }
};

/// SceneView::lightBvhTrails of a light the BVH does not hold (an infinite light, a light of no power).
constexpr uint64_t kNoLightTrail = ~uint64_t(0);

} // namespace urbis
