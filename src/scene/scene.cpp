#include "scene/scene.h"

#include "scene/prim_ref.h"

#include <stdexcept>

namespace urbis {

namespace {

/// World bounds of a wall's slab, from w = -depthBack to w = depthFront.
Bounds3f wallBounds(const WallRecord& wall) {
    Bounds3f b;
    for (int k = 0; k < 8; ++k)
        b.extend(wall.worldFromWall(k & 1 ? wall.width : 0.0f, k & 2 ? wall.height : 0.0f,
                                    k & 4 ? wall.depthFront : -wall.depthBack));
    return b;
}

} // namespace

Scene Scene::build(const TriangleMesh& mesh, std::vector<Material> materials, const std::vector<WallRecord>& walls) {
    if (mesh.size() > kPrimIndexMask || walls.size() > kPrimIndexMask)
        throw std::length_error("scene: more than 2^28 primitives of one kind");
    std::vector<Bounds3f> bounds(mesh.size() + walls.size());
    for (size_t i = 0; i < mesh.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        bounds[i].extend(t.p0);
        bounds[i].extend(t.p1);
        bounds[i].extend(t.p2);
    }
    for (size_t i = 0; i < walls.size(); ++i) bounds[mesh.size() + i] = wallBounds(walls[i]);
    Bvh bvh = buildBvh(bounds);
    Scene scene;
    scene.nodes = std::move(bvh.nodes);
    scene.triangles.reserve(mesh.size());
    scene.info.reserve(mesh.size());
    scene.walls.reserve(walls.size());
    if (!walls.empty()) scene.primRefs.reserve(bvh.primOrder.size());
    for (uint32_t prim : bvh.primOrder) {
        if (prim < mesh.size()) {
            if (!walls.empty()) scene.primRefs.push_back(makePrimRef(PrimKind::Triangle, uint32_t(scene.triangles.size())));
            scene.triangles.push_back(mesh.triangles[prim]);
            scene.info.push_back(mesh.info[prim]);
        } else {
            scene.primRefs.push_back(makePrimRef(PrimKind::Wall, uint32_t(scene.walls.size())));
            scene.walls.push_back(walls[prim - mesh.size()]);
        }
    }
    scene.materials = std::move(materials);
    return scene;
}

SceneView Scene::view() const {
    return SceneView{TriangleSceneView{nodes.data(), triangles.data(), uint32_t(triangles.size())},
                     info.data(),
                     primRefs.empty() ? nullptr : primRefs.data(),
                     walls.data(),
                     uint32_t(walls.size()),
                     materials.data(),
                     ground,
                     sun,
                     sky};
}

SceneMemory Scene::memory() const {
    return SceneMemory{triangles.size() * sizeof(Triangle), info.size() * sizeof(TriangleInfo),
                       walls.size() * sizeof(WallRecord),  primRefs.size() * sizeof(uint32_t),
                       materials.size() * sizeof(Material), nodes.size() * sizeof(BvhNode)};
}

} // namespace urbis
