// A triangle-only BVH as a view (host+device POD): what tests and benchmarks of the triangle
// traversal alone take (geometry/triangle_scene.h).
#pragma once

#include "accel/bvh_node.h"
#include "accel/wide_bvh_node.h"
#include "scene/triangle.h"

#include <cstdint>

namespace urbis {

/// Non-owning view of a triangle BVH: nodes from buildBvh over the triangles' bounds and the
/// triangles reordered by its primOrder (triangles[i] = original[primOrder[i]]).
struct TriangleSceneView {
    const BvhNode* nodes;
    const Triangle* triangles;
    uint32_t triangleCount;
};

/// The same over an 8-wide compressed BVH: nodes from buildWideBvh, triangles in its primOrder.
struct WideTriangleSceneView {
    const WideBvhNode* nodes;
    const Triangle* triangles;
    uint32_t triangleCount;
};

} // namespace urbis
