// The kinds list and what a trace returns: one scene of a triangle, a procedural wall and the
// ground, traced at each; the hit's kind, position, frame and uv in the kind's own terms; the
// ground hangs from the BVH's root; every leaf slot lies in its kind's range.
#include "facade_test_walls.h"

#include "geometry/scene_intersect.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace urbis;

namespace {

/// A 10 m wide, 9 m high punched wall along +x at z = 0, facing +z: three slots, three floors.
WallRecord testWall() {
    WallRecord w;
    test::giveTestFacade(WallStyle::Punched, w);
    w.flags = 0;
    w.origin = {0, 0, 0};
    w.axisU = {1, 0, 0};
    w.normal = {0, 0, 1};
    w.width = 10.0f;
    w.height = 9.0f;
    w.slots = 3;
    w.floors = 3;
    w.slotWidth = 3.0f;
    w.floorHeight = 2.8f;
    w.windowWidth = 1.2f;
    w.windowHeight = 1.4f;
    w.object = 7;
    return w;
}

Scene testScene() {
    TriangleMesh mesh;
    mesh.add({{20, 0, -5}, {30, 0, -5}, {20, 10, -5}}, TriangleInfo{3, 5, uint32_t(SurfacePart::Roof)});
    std::vector<Material> materials(12);
    return Scene::build({.mesh = mesh, .materials = materials, .walls = {testWall()},
                         .grounds = {GroundRecord::around(0, 0, 0, 11)}});
}

void expectUnitFrame(const SurfaceHit& h) {
    const Frame f = h.frame();
    EXPECT_NEAR(length(f.x), 1.0f, 1e-6f);
    EXPECT_NEAR(length(f.y), 1.0f, 1e-6f);
    EXPECT_NEAR(dot(f.x, f.z), 0.0f, 1e-6f);
    EXPECT_NEAR(dot(f.y, f.z), 0.0f, 1e-6f);
    const Vec3f c = cross(f.x, f.y);
    EXPECT_NEAR(dot(c, f.z), 1.0f, 1e-6f);   // right-handed
}

} // namespace

TEST(PrimKinds, ListIndicesAndCosts) {
    EXPECT_EQ(kPrimKindCount, 8u);
    EXPECT_EQ(kPrimKindOf<Triangle>, 0u);
    EXPECT_EQ(kPrimKindOf<WallRecord>, 1u);
    EXPECT_EQ(kPrimKindOf<GroundRecord>, 2u);
    EXPECT_EQ(kPrimKindOf<LampRecord>, 3u);
    EXPECT_EQ(kPrimKindOf<TerrainRecord>, 4u);
    EXPECT_TRUE(kKindAtBvhRoot<kPrimKindOf<TerrainRecord>>);
    EXPECT_EQ(kPrimKindOf<TreeRecord>, 5u);
    EXPECT_TRUE(kCostlyKind<kPrimKindOf<TreeRecord>>);
    EXPECT_EQ(kPrimKindOf<PlanetRecord>, 6u);
    EXPECT_TRUE(kCostlyKind<kPrimKindOf<PlanetRecord>>);
    EXPECT_EQ(kPrimKindOf<ForestRecord>, 7u);
    EXPECT_TRUE(kCostlyKind<kPrimKindOf<ForestRecord>>);
    EXPECT_FALSE(kCostlyKind<kPrimKindOf<Triangle>>);
    EXPECT_TRUE(kCostlyKind<kPrimKindOf<WallRecord>>);
    EXPECT_TRUE(kCostlyKind<kPrimKindOf<LampRecord>>);
    EXPECT_TRUE(kKindAtBvhRoot<kPrimKindOf<GroundRecord>>);
    EXPECT_FALSE(kKindAtBvhRoot<kPrimKindOf<WallRecord>>);
}

TEST(PrimKinds, LeafSlotsLieInTheirKindsRangeAndTheGroundAtTheRoot) {
    const Scene scene = testScene();
    const SceneView view = scene.view();
    ASSERT_EQ(scene.grounds.size(), 1u);
    EXPECT_EQ(view.kindEnd[0], 1u);
    EXPECT_EQ(view.kindEnd[1], 1u + uint32_t(scene.walls.size()));
    EXPECT_EQ(view.kindEnd[2], view.kindEnd[1] + 1u);
    EXPECT_TRUE(view.costlyLeaves);
    // The ground hangs from the root; every leaf position reaches its own slot, walls' leaves costly.
    bool groundAtRoot = false;
    for (int l = 0; l < kWideBvhWidth; ++l)
        groundAtRoot |= scene.nodes[0].leafSize(l) == 1 &&
                        scene.leafSlots[wideLeafFirst(scene.nodes[0], l)] == view.kindEnd[1];
    EXPECT_TRUE(groundAtRoot);
    std::vector<uint32_t> slots = scene.leafSlots;
    std::sort(slots.begin(), slots.end());
    for (uint32_t i = 0; i < slots.size(); ++i) ASSERT_EQ(slots[i], i);
    EXPECT_EQ(slots.size(), size_t(view.kindEnd[kPrimKindCount - 1]));
    for (const WideBvhNode& node : scene.nodes)
        for (int l = 0; l < kWideBvhWidth; ++l)
            for (uint32_t i = 0; i < node.leafSize(l); ++i) {
                const uint32_t slot = scene.leafSlots[wideLeafFirst(node, l) + i];
                const bool wall = slot >= view.kindEnd[0] && slot < view.kindEnd[1];
                EXPECT_EQ(node.costlyLeaf(l), wall) << "slot " << slot;
            }
}

TEST(SurfaceHitRecord, EachKindGivesPositionFrameUvMaterialAndIds) {
    const Scene scene = testScene();
    const SceneView view = scene.view();

    // The ground, from above: uv is world (x, z).
    const Ray down{{-40.0f, 50.0f, 60.0f}, normalize(Vec3f{-1.0f, -2.0f, 0.5f})};
    const SurfaceHit g = intersectScene(view, down);
    ASSERT_TRUE(g.valid());
    EXPECT_EQ(g.kind, kPrimKindOf<GroundRecord>);
    EXPECT_NEAR(g.position.y, 0.0f, 1e-4f);
    EXPECT_NEAR(g.uv.x, g.position.x, 1e-6f);
    EXPECT_NEAR(g.uv.y, g.position.z, 1e-6f);
    EXPECT_EQ(g.normal.y, 1.0f);
    EXPECT_EQ(g.material, 11u);
    EXPECT_EQ(g.object, 0u);
    expectUnitFrame(g);
    // From below nothing: the ground is hit from above only (rays refracted into water pass under
    // its level, docs/water.md).
    EXPECT_FALSE(intersectScene(view, Ray{{-40.0f, -5.0f, 60.0f}, {0, 1, 0}}).valid());

    // The wall's left margin, straight on: uv is (u, v) in metres on the wall.
    const Ray atWall{{0.25f, 4.0f, 20.0f}, {0, 0, -1}};
    const SurfaceHit w = intersectScene(view, atWall);
    ASSERT_TRUE(w.valid());
    EXPECT_EQ(w.kind, kPrimKindOf<WallRecord>);
    EXPECT_NEAR(w.t, 20.0f, 1e-4f);
    EXPECT_NEAR(w.uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(w.uv.y, 4.0f, 1e-5f);
    EXPECT_EQ(w.normal.z, 1.0f);
    EXPECT_EQ(w.object, 7u);
    EXPECT_EQ(w.part, SurfacePart::Facade);
    EXPECT_EQ(w.material, 1u);
    expectUnitFrame(w);

    // The triangle: uv are the barycentrics of p1 and p2, and its info's ids.
    const Ray atTriangle{{22.0f, 3.0f, 10.0f}, {0, 0, -1}};
    const SurfaceHit t = intersectScene(view, atTriangle);
    ASSERT_TRUE(t.valid());
    EXPECT_EQ(t.kind, kPrimKindOf<Triangle>);
    EXPECT_NEAR(t.position.z, -5.0f, 1e-5f);
    EXPECT_NEAR(t.uv.x, 0.2f, 1e-5f);
    EXPECT_NEAR(t.uv.y, 0.3f, 1e-5f);
    EXPECT_EQ(t.material, 3u);
    EXPECT_EQ(t.object, 5u);
    EXPECT_EQ(t.part, SurfacePart::Roof);
    EXPECT_EQ(t.normal.z, 1.0f);
    expectUnitFrame(t);

    // Shadow rays: the wall blocks, the sky does not.
    EXPECT_TRUE(occludedScene(view, atWall));
    EXPECT_FALSE(occludedScene(view, Ray{{0.25f, 4.0f, 20.0f}, {0, 1, 0}}));
}

TEST(SceneArrays, MemoryListsEveryArrayOnce) {
    const Scene scene = testScene();
    const SceneMemory memory = scene.memory();
    size_t sum = 0, arrays = 0;
    memory.forEach([&](const char*, size_t bytes) {
        sum += bytes;
        ++arrays;
    });
    EXPECT_EQ(arrays, 31u);   // the eight kinds' records, triangle info, nodes, leaf slots, materials, road segments, the ten light arrays, the atmosphere's three tables and the terrain's samples, the clouds' layer and three tables
    EXPECT_EQ(sum, memory.total());
    EXPECT_EQ(memory.grounds, sizeof(GroundRecord));
    EXPECT_EQ(memory.walls, scene.walls.size() * sizeof(WallRecord));
    EXPECT_EQ(memory.nodes, scene.nodes.size() * sizeof(WideBvhNode));
}
