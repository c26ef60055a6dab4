// Small night scenes for the night-light tests of both backends: a wall of lit windows (a hand-made
// facade record with its materials) and a scene of walls, lamps and a mesh under a set sun and a
// black sky.
#pragma once

#include "citygen/window_schedule.h"
#include "facade_test_walls.h"
#include "scene/scene.h"

#include <utility>
#include <vector>

namespace urbis::test {

/// `mesh`, `walls` and `lamps` under a sun 10 degrees below the horizon and a black sky.
inline Scene nightScene(const TriangleMesh& mesh, std::vector<Material> materials, const std::vector<WallRecord>& walls,
                        const std::vector<LampRecord>& lamps) {
    Scene scene = Scene::build({.mesh = mesh, .materials = std::move(materials), .walls = walls, .lamps = lamps});
    scene.sun = makeSun(-10.0f, 200.0f, 0.27f, {0.0f, 0.0f, 0.0f});   // set: no ground here hides it
    scene.sky = Sky::uniform({0, 0, 0});
    return scene;
}

/// A facade wall of `slots` x `floors` cells, facing +z from the plane z = 0, its rooms lit with
/// `share`; its materials from 1 (wall) and 2 (facade: glass, rooms, ...).
inline WallRecord testWall(uint32_t slots, uint32_t floors, float share, uint32_t seed) {
    WallRecord w{.origin = {-0.5f * (float(slots) * 3.0f + 1.0f), 0.0f, 0.0f}, .axisU = {1, 0, 0}, .normal = {0, 0, 1},
                 .slotWidth = 3.0f, .floorHeight = 3.2f, .slots = uint16_t(slots), .floors = uint16_t(floors),
                 .windowWidth = 1.4f, .windowHeight = 1.6f, .object = 1, .cellSeed = seed};
    giveTestFacade(WallStyle::Punched, w);
    w.flags = 0;
    w.width = w.gridWidth() + 1.0f;
    w.height = w.gridHeight() + 0.9f;
    w.litChance = w.shopLitChance = chanceByte(share);
    return w;
}

/// Materials of testWall: 0 a plane, 1 the wall, 2.. the facade's (FacadeMaterial order).
inline std::vector<Material> wallMaterials() {
    std::vector<Material> m{Material{{0.5f, 0.5f, 0.5f}}, Material{{0.6f, 0.55f, 0.5f}}};
    Material glass{{0.85f, 0.9f, 0.9f}};
    glass.kind = MaterialKind::Glass;
    Material lit{{0.45f, 0.40f, 0.33f}};
    lit.emission = {6.7f, 4.0f, 1.9f};   // a thousand times a city's, so that the tests converge fast
    m.push_back(glass);
    m.push_back(Material{{0.3f, 0.3f, 0.3f}});
    m.push_back(lit);
    for (int i = 0; i < 4; ++i) m.push_back(Material{{0.4f, 0.4f, 0.4f}});
    return m;
}

} // namespace urbis::test
