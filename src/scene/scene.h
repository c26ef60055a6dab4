// The host-side scene: flat arrays in BVH leaf order, the BVH itself, lights, and what it all costs.
#pragma once

#include "accel/bvh_build.h"
#include "citygen/triangle_mesh.h"
#include "scene/scene_view.h"

#include <vector>

namespace urbis {

/// Bytes the scene holds, by kind.
struct SceneMemory {
    size_t triangles = 0, triangleInfo = 0, materials = 0, bvh = 0;
    size_t total() const { return triangles + triangleInfo + materials + bvh; }
};

struct Scene {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;      ///< in BVH leaf order
    std::vector<TriangleInfo> info;       ///< same order as triangles
    std::vector<Material> materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;

    /// Builds the BVH over `mesh` and stores its triangles in leaf order.
    static Scene build(const TriangleMesh& mesh, std::vector<Material> materials);
    SceneView view() const;
    SceneMemory memory() const;
};

} // namespace urbis
