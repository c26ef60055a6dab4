#include "scene/scene.h"

namespace urbis {

Scene Scene::build(const TriangleMesh& mesh, std::vector<Material> materials) {
    std::vector<Bounds3f> bounds(mesh.size());
    for (size_t i = 0; i < mesh.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        bounds[i].extend(t.p0);
        bounds[i].extend(t.p1);
        bounds[i].extend(t.p2);
    }
    Bvh bvh = buildBvh(bounds);
    Scene scene;
    scene.nodes = std::move(bvh.nodes);
    scene.triangles.resize(mesh.size());
    scene.info.resize(mesh.size());
    for (size_t i = 0; i < bvh.primOrder.size(); ++i) {
        scene.triangles[i] = mesh.triangles[bvh.primOrder[i]];
        scene.info[i] = mesh.info[bvh.primOrder[i]];
    }
    scene.materials = std::move(materials);
    return scene;
}

SceneView Scene::view() const {
    return SceneView{TriangleSceneView{nodes.data(), triangles.data(), uint32_t(triangles.size())}, info.data(),
                     materials.data(), ground, sun, sky};
}

SceneMemory Scene::memory() const {
    return SceneMemory{triangles.size() * sizeof(Triangle), info.size() * sizeof(TriangleInfo),
                       materials.size() * sizeof(Material), nodes.size() * sizeof(BvhNode)};
}

} // namespace urbis
