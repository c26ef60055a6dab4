// meshBridges on hand-made roads: the deck over a crossing road lies high above it, parapets stand on
// both edges, piers stand under the deck's high part and off the road below, and bad input is counted.
#include "geometry/scene_intersect.h"
#include "scene/scene.h"
#include "streets/bridge_deck.h"
#include "streets/bridge_mesher.h"
#include "streets/road_elevation.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

Road way(std::vector<Vec2d> line, bool bridge, float width = 10.0f) {
    Road r;
    r.centerline = std::move(line);
    r.bridge = bridge;
    r.layer = bridge ? 1 : 0;
    r.width = width;
    return r;
}

/// A line from a to b, a point every ~10 m.
std::vector<Vec2d> line(Vec2d a, Vec2d b) {
    const int n = std::max(1, int(std::lround(std::hypot(b.x - a.x, b.y - a.y) / 10.0)));
    std::vector<Vec2d> out;
    for (int i = 0; i <= n; ++i) out.push_back({a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n});
    return out;
}

/// An east-west bridge of 200 m on approaches of 300 m, over a north-south ground road at x = 105.
struct Overpass {
    std::vector<Road> roads;
    StreetOptions options;
    StreetMesh out;
    Scene scene;

    Overpass() {
        roads = {way(line({-300, 0}, {0, 0}), false), way(line({0, 0}, {200, 0}), true),
                 way(line({200, 0}, {500, 0}), false), way(line({105, -150}, {105, 150}), false, 6.0f)};
        roads[1].sidewalkLeftWidth = 2.0f;
        roads[1].sidewalkRightWidth = 2.0f;
        options.firstObject = 7;
        meshBridges(roads, roadElevations(roads), options, out);
        scene = Scene::build({.mesh = out.mesh, .materials = streetMaterials()});
    }

    /// The first hit of a vertical ray at local (x, y) from height `from`, up or down.
    SurfaceHit vertical(double x, double y, float from, bool up) const {
        return traceScene(scene.view(), Ray{worldFromStreet({x, y}, from), Vec3f{0, up ? 1.0f : -1.0f, 0}}, false);
    }
};

} // namespace

TEST(StreetsBridgeStructure, DeckLiesHighAboveTheRoadItCrosses) {
    const Overpass c;
    const SurfaceHit under = c.vertical(105, 0, kRoadLevel + 0.05f, true);
    ASSERT_TRUE(under.valid());
    EXPECT_EQ(under.part, SurfacePart::BridgeDeck);
    EXPECT_EQ(under.object, 7u + 1u);
    EXPECT_GE(under.position.y - kRoadLevel, 4.0f) << "the underside clears the road below by 4 m";
    const SurfaceHit above = c.vertical(105, 0, 100.0f, false);
    ASSERT_TRUE(above.valid());
    EXPECT_EQ(above.part, SurfacePart::BridgeDeck);
    EXPECT_NEAR(above.position.y, kRoadLevel + 6.0f - kDeckThickness, 1e-3);
}

TEST(StreetsBridgeStructure, ParapetsStandOnBothEdges) {
    const Overpass c;
    // The deck reaches 5 + 2 m each side; the parapets take its outer 0.3 m, on the sidewalks' level.
    for (double side : {-1.0, 1.0}) {
        const SurfaceHit hit = c.vertical(60, side * 6.85, 100.0f, false);
        ASSERT_TRUE(hit.valid());
        EXPECT_EQ(hit.part, SurfacePart::Parapet);
        EXPECT_NEAR(hit.position.y, 6.0f + kSidewalkLevel + kParapetHeight, 1e-3);
        const SurfaceHit outside = c.vertical(60, side * 7.05, 100.0f, false);
        EXPECT_FALSE(outside.valid()) << "nothing beyond the deck's edge";
    }
}

TEST(StreetsBridgeStructure, PiersStandUnderTheHighDeckAndOffTheRoadBelow) {
    const Overpass c;
    size_t pierTriangles = 0;
    for (size_t t = 0; t < c.out.mesh.size(); ++t) {
        if (c.out.mesh.info[t].part != uint32_t(SurfacePart::Pier)) continue;
        ++pierTriangles;
        for (const Vec3f& p : {c.out.mesh.triangles[t].p0, c.out.mesh.triangles[t].p1, c.out.mesh.triangles[t].p2}) {
            EXPECT_TRUE(p.y == 0.0f || std::fabs(p.y - (6.0f + kRoadLevel - kDeckThickness)) < 1e-3f)
                << "a pier runs from the ground to the underside";
            EXPECT_GT(std::fabs(p.x - 105.0f), 3.0f) << "no pier on the road below";
            EXPECT_GE(p.x, 0.0f);
            EXPECT_LE(p.x, 200.0f);
        }
    }
    // Stations every 30 m from 15 m: 15, 45, 75, 105 (moved to 109, off the road below), 135, 165,
    // 195 (moved to 191, off the approach); each one column of 8 triangles (14 m of deck: one column
    // per ~10 m).
    EXPECT_EQ(pierTriangles, 7u * 8u);
}

TEST(StreetsBridgeStructure, ApproachesStandOnWalls) {
    const Overpass c;
    // 50 m before the deck the approach is 3 m up, on walls down to the ground.
    const SurfaceHit wall = traceScene(c.scene.view(), Ray{worldFromStreet({-50, 20}, 1.0), Vec3f{0, 0, 1}}, false);
    ASSERT_TRUE(wall.valid());
    EXPECT_EQ(wall.part, SurfacePart::BridgeDeck);
    EXPECT_EQ(wall.object, 7u);
    EXPECT_NEAR(wall.position.z, -5.0f, 1e-3) << "the wall follows the carriageway's edge";
    // 150 m before it the approach is on the ground: nothing there.
    EXPECT_FALSE(traceScene(c.scene.view(), Ray{worldFromStreet({-150, 20}, 0.1), Vec3f{0, 0, 1}}, false).valid());
    EXPECT_EQ(c.out.counts.at("bridges"), 1u);
    EXPECT_EQ(c.out.objects, 4u) << "an id for every road";
    EXPECT_EQ(c.out.trianglesByKind.at("bridges"), c.out.mesh.size());
}

TEST(StreetsBridgeStructure, ShortBridgeLandingOnJunctionsStillClearsTheRoadBelow) {
    // A 30 m bridge between two junctions 30 m apart, over a road at x = 15: the slope alone would
    // allow 0.9 m; the crossing holds the segment over the road at the clearance, and the deck comes
    // down at the slope from there (0.6 m over 10 m), the junctions rising with it.
    std::vector<Road> roads = {way(line({0, 0}, {30, 0}), true),    way(line({0, 0}, {-120, 0}), false),
                               way(line({0, 0}, {0, 120}), false),  way(line({30, 0}, {150, 0}), false),
                               way(line({30, 0}, {30, 120}), false), way(line({15, -50}, {15, 50}), false, 6.0f)};
    const std::vector<std::vector<float>> e = roadElevations(roads);
    ASSERT_EQ(e[0].size(), 4u);
    EXPECT_FLOAT_EQ(e[0][1], 6.0f);
    EXPECT_FLOAT_EQ(e[0][2], 6.0f);
    EXPECT_NEAR(e[0].front(), 5.4f, 1e-4);
    EXPECT_NEAR(e[0].back(), 5.4f, 1e-4);
    for (float h : e[5]) EXPECT_EQ(h, 0.0f) << "the road below stays on the ground";
    for (size_t w = 1; w < 5; ++w) {
        EXPECT_NEAR(e[w].front(), 5.4f, 1e-4) << "every way at the junction rises with it";
        for (size_t i = 1; i < e[w].size(); ++i) EXPECT_LE(std::fabs(e[w][i] - e[w][i - 1]), 0.06f * 10.0f + 1e-4f);
        EXPECT_EQ(e[w].back(), 0.0f) << "and ramps down to the ground";
    }
    StreetMesh out;
    meshBridges(roads, e, StreetOptions{}, out);
    const Scene scene = Scene::build({.mesh = out.mesh, .materials = streetMaterials()});
    const SurfaceHit under =
        traceScene(scene.view(), Ray{worldFromStreet({15, 0}, kRoadLevel + 0.05), Vec3f{0, 1, 0}}, false);
    ASSERT_TRUE(under.valid());
    EXPECT_EQ(under.part, SurfacePart::BridgeDeck);
    EXPECT_GE(under.position.y - kRoadLevel, 4.0f);
}

TEST(StreetsBridgeStructure, BadBridgesAreCountedNotMeshed) {
    std::vector<Road> roads = {way({{0, 0}}, true), way({{0, 0}, {0, 0}}, true), way({{NAN, 0}, {10, 0}}, true),
                               way({{1e300, 0}, {-1e300, 0}}, true), way(line({0, 0}, {50, 0}), true)};
    roads[4].tunnel = true;
    StreetMesh out;
    meshBridges(roads, roadElevations(roads), StreetOptions{}, out);
    EXPECT_EQ(out.mesh.size(), 0u);
    EXPECT_EQ(out.dropped["bridge_degenerate"], 4u);
    EXPECT_EQ(out.dropped["bridge_not_drawn"], 1u);
    StreetMesh mismatched;
    meshBridges(roads, {}, StreetOptions{}, mismatched);
    EXPECT_EQ(mismatched.dropped["bridge_elevations_missing"], 5u);
}
