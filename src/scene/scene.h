// The host-side scene: flat arrays in BVH leaf order, the BVH itself, lights, and what it all costs.
#pragma once

#include "accel/bvh_build.h"
#include "citygen/triangle_mesh.h"
#include "scene/scene_view.h"

#include <vector>

namespace urbis {

/// Bytes the scene holds, by kind.
struct SceneMemory {
    size_t triangles = 0, triangleInfo = 0, walls = 0, primRefs = 0, materials = 0, bvh = 0;
    size_t total() const { return triangles + triangleInfo + walls + primRefs + materials + bvh; }
};

/// Every array here is mirrored to the device as it is: nodes, triangles, info, primRefs, walls, materials.
struct Scene {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;      ///< in the order the BVH leaves reach them
    std::vector<TriangleInfo> info;       ///< same order as triangles
    std::vector<uint32_t> primRefs;       ///< per leaf slot, a PrimRef; empty when there are only triangles
    std::vector<WallRecord> walls;        ///< in the order the BVH leaves reach them
    std::vector<Material> materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;

    /// Builds one BVH over the triangles of `mesh` and the procedural `walls`, and stores both in
    /// leaf order. Without walls every leaf slot is a triangle and primRefs stays empty.
    static Scene build(const TriangleMesh& mesh, std::vector<Material> materials,
                       const std::vector<WallRecord>& walls = {});
    SceneView view() const;
    SceneMemory memory() const;
};

} // namespace urbis
