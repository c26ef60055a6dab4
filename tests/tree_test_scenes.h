// A grove for the tree tests: broadleaves and conifers of several sizes on a ground plane, made by
// the same path as a city's trees (treeRecordOf, or the twin's meshTree); and a forest on its own.
#pragma once

#include "nature/tree_mesher.h"
#include "nature/tree_records.h"
#include "scene/scene.h"
#include "scene/sun.h"

#include <vector>

namespace urbis::test {

/// `rows` x `rows` trees 9 m apart around the origin (model metres), every third a conifer, with
/// their own objects (1, 2, ...) and their materials after the ground's (material 0).
inline std::vector<TreeRecord> groveRecords(int rows) {
    std::vector<TreeRecord> records;
    const TreeOptions options;
    for (int i = 0; i < rows * rows; ++i) {
        Tree t;
        t.position = {9.0 * (i % rows - 0.5 * (rows - 1)), 9.0 * (i / rows - 0.5 * (rows - 1))};
        t.height = 6.0f + float(i % 5);
        t.leafType = i % 3 == 2 ? LeafType::Needleleaved : LeafType::Broadleaved;
        records.push_back(treeRecordOf(t, 1000u + uint32_t(i), options, uint32_t(i + 1), 1));
    }
    return records;
}

/// The grove as a scene: sphere-traced trees, or (`twin`) their triangles.
inline Scene groveScene(int rows, bool twin) {
    std::vector<Material> materials{Material{Vec3f{0.2f, 0.2f, 0.18f}}};
    for (const Material& m : treeMaterials(TreeOptions{})) materials.push_back(m);
    const std::vector<TreeRecord> records = groveRecords(rows);
    TriangleMesh mesh;
    if (twin)
        for (const TreeRecord& r : records) meshTree(r, mesh);
    Scene scene = Scene::build({.mesh = mesh, .materials = materials, .grounds = {GroundRecord::around(0, 0, 0, 0)},
                                .trees = twin ? std::vector<TreeRecord>{} : records});
    scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    return scene;
}

/// A forest alone on the ground plane (material 0), its trees' materials after it (material 1 on), in sunlight.
inline Scene forestScene(const ForestRecord& forest) {
    std::vector<Material> materials{Material{Vec3f{0.2f, 0.2f, 0.18f}}};
    for (const Material& m : treeMaterials(TreeOptions{})) materials.push_back(m);
    Scene scene = Scene::build({.materials = materials, .grounds = {GroundRecord::around(0, 0, 0, 0)},
                                .forests = {forest}});
    scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    return scene;
}

} // namespace urbis::test
