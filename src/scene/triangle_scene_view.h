// A triangle-only BVH as a view (host+device POD): what tests and benchmarks of the triangle
// traversal alone take (geometry/wide_triangle_scene.h).
#pragma once

#include "accel/wide_bvh_node.h"
#include "scene/triangle.h"
#include "scene/triangle_block.h"

#include <cstdint>

namespace urbis {

/// Non-owning view of a triangle-only 8-wide compressed BVH (buildWideTriangleScene): nodes from
/// buildWideBvh whose leaves address blocks (groupWideLeaves), the blocks, and the triangles in the
/// BVH's primOrder, which the blocks' prim indices and Hit::prim index.
struct WideTriangleSceneView {
    const WideBvhNode* nodes;
    const TriangleBlock* blocks;
    const Triangle* triangles;
    uint32_t triangleCount;
};

} // namespace urbis
