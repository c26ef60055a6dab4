// The options of the binned SAH build that every BVH over primitive bounds starts from (host):
// buildBinaryBvh (binary_bvh.h), collapsed into the 8-wide BVH by buildWideBvh (wide_bvh_build.h).
#pragma once

#include <cstdint>

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

} // namespace urbis
