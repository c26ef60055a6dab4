// meshRailways: rails at the gauge on the ballast's top, trams flush in the street, tunnels not
// drawn, bridges on a deck high above the ground.
#include "geometry/scene_intersect.h"
#include "scene/scene.h"
#include "streets/bridge_deck.h"
#include "streets/railway_mesher.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

/// An east-west track from x0 to x1 at y = 0, a point every 10 m.
Railway track(double x0, double x1, RailKind kind = RailKind::Rail) {
    Railway r;
    for (double x = x0; x <= x1; x += 10) r.centerline.push_back({x, 0});
    r.kind = kind;
    r.embedded = kind == RailKind::Tram;
    return r;
}

StreetMesh meshed(std::vector<Railway> railways) {
    CityModel city;
    city.roads.resize(3);  // railways' object ids come after the roads'
    city.railways = std::move(railways);
    StreetOptions options;
    options.firstObject = 10;
    StreetMesh out;
    meshRailways(city, options, out);
    return out;
}

/// Lowest and highest height, and least and greatest distance from the centerline (|north|), of the
/// vertices of `part`'s triangles.
struct Extent {
    float lowest = 1e30f, highest = -1e30f, nearest = 1e30f, farthest = -1e30f;
    size_t triangles = 0;
};

Extent extentOf(const StreetMesh& out, SurfacePart part) {
    Extent e;
    for (size_t t = 0; t < out.mesh.size(); ++t) {
        if (out.mesh.info[t].part != uint32_t(part)) continue;
        ++e.triangles;
        for (const Vec3f& p : {out.mesh.triangles[t].p0, out.mesh.triangles[t].p1, out.mesh.triangles[t].p2}) {
            e.lowest = std::min(e.lowest, p.y);
            e.highest = std::max(e.highest, p.y);
            e.nearest = std::min(e.nearest, std::fabs(p.z));
            e.farthest = std::max(e.farthest, std::fabs(p.z));
        }
    }
    return e;
}

SurfaceHit down(const Scene& scene, double x, double y) {
    return traceScene(scene.view(), Ray{worldFromStreet({x, y}, 50.0), Vec3f{0, -1, 0}}, false);
}

} // namespace

TEST(StreetsRailway, RailsAtTheGaugeOnTheBallast) {
    Railway broad = track(0, 100);
    broad.gauge = 1.668f;
    for (const Railway& r : {track(0, 100), broad}) {
        const StreetMesh out = meshed({r});
        const Extent rails = extentOf(out, SurfacePart::Rail), ballast = extentOf(out, SurfacePart::Ballast);
        EXPECT_NEAR(rails.nearest * 2, r.gauge, 1e-4) << "inner faces the gauge apart";
        EXPECT_NEAR(rails.farthest - rails.nearest, kRailWidth, 1e-4);
        EXPECT_FLOAT_EQ(rails.lowest, kBallastLevel) << "rails stand on the ballast's top, not floating";
        EXPECT_FLOAT_EQ(rails.highest, kBallastLevel + kRailHeight);
        EXPECT_FLOAT_EQ(ballast.highest, kBallastLevel);
        EXPECT_FLOAT_EQ(ballast.lowest, 0.0f);
        EXPECT_GT(ballast.farthest, rails.farthest + 0.5f);
        EXPECT_EQ(out.counts.at("railways"), 1u);
        EXPECT_EQ(out.trianglesByKind.at("railways"), out.mesh.size());
        for (const TriangleInfo& info : out.mesh.info) EXPECT_EQ(info.object, 10u) << "after the parts meshed before: none";
        EXPECT_EQ(out.objects, 1u);
        // Seen from above: a rail's top over each rail, ballast between and beside them.
        const Scene scene = Scene::build({.mesh = out.mesh, .materials = streetMaterials()});
        const SurfaceHit onRail = down(scene, 50, (r.gauge + kRailWidth) / 2);
        ASSERT_TRUE(onRail.valid());
        EXPECT_EQ(onRail.part, SurfacePart::Rail);
        EXPECT_NEAR(onRail.position.y, kBallastLevel + kRailHeight, 1e-4);
        const SurfaceHit between = down(scene, 50, 0);
        ASSERT_TRUE(between.valid());
        EXPECT_EQ(between.part, SurfacePart::Ballast);
        EXPECT_NEAR(between.position.y, kBallastLevel, 1e-4);
    }
}

TEST(StreetsRailway, TramsLieFlushInTheStreet) {
    const StreetMesh out = meshed({track(0, 100, RailKind::Tram)});
    EXPECT_EQ(extentOf(out, SurfacePart::Ballast).triangles, 0u);
    const Extent rails = extentOf(out, SurfacePart::Rail);
    EXPECT_GT(rails.triangles, 0u);
    EXPECT_FLOAT_EQ(rails.lowest, kRoadLevel + kEmbeddedRailRise);
    EXPECT_FLOAT_EQ(rails.highest, kRoadLevel + kEmbeddedRailRise);
    EXPECT_NEAR(rails.nearest * 2, 1.435f, 1e-4);
}

TEST(StreetsRailway, TunnelsAndCoveredTracksAreNotDrawn) {
    std::vector<Railway> hidden(4, track(0, 100));
    hidden[0].tunnel = true;
    hidden[1].covered = true;
    hidden[2].underground = true;
    hidden[3].layer = -1;
    const StreetMesh out = meshed(hidden);
    EXPECT_EQ(out.mesh.size(), 0u);
    EXPECT_EQ(out.counts.at("railways"), 0u);
    EXPECT_EQ(out.dropped.at("railway_not_at_surface"), 4u);
}

TEST(StreetsRailway, BadTracksAreCounted) {
    Railway point = track(0, 0), nan = track(0, 100), gauge = track(0, 100);
    nan.centerline[3].x = NAN;
    gauge.gauge = 0.0f;
    const StreetMesh out = meshed({point, nan, gauge});
    EXPECT_EQ(out.mesh.size(), 0u);
    EXPECT_EQ(out.dropped.at("railway_degenerate"), 3u);
}

TEST(StreetsRailway, BridgeCarriesTheTrackHigh) {
    // A 200 m railway bridge (layer 1) between approaches of 300 m ending at dead ends.
    Railway bridge = track(300, 500);
    bridge.bridge = true;
    bridge.layer = 1;
    const StreetMesh out = meshed({track(0, 300), bridge, track(500, 800)});
    const Scene scene = Scene::build({.mesh = out.mesh, .materials = streetMaterials()});
    const SurfaceHit rail = down(scene, 400, (1.435 + kRailWidth) / 2);
    ASSERT_TRUE(rail.valid());
    EXPECT_EQ(rail.part, SurfacePart::Rail);
    EXPECT_NEAR(rail.position.y, 6.0f + kBallastLevel + kRailHeight, 1e-3);
    const SurfaceHit under = traceScene(scene.view(), Ray{worldFromStreet({400, 0}, 0.5), Vec3f{0, 1, 0}}, false);
    ASSERT_TRUE(under.valid());
    EXPECT_EQ(under.part, SurfacePart::BridgeDeck);
    EXPECT_NEAR(under.position.y, 6.0f + kRoadLevel - kDeckThickness, 1e-3);
    // Piers every 30 m from 15 m along the bridge: one at x = 405, seen from the side under the deck.
    const SurfaceHit pier = traceScene(scene.view(), Ray{worldFromStreet({405, -1.5}, 2.0), Vec3f{0, 0, -1}}, false);
    ASSERT_TRUE(pier.valid());
    EXPECT_EQ(pier.part, SurfacePart::Pier);
    EXPECT_NEAR(pier.position.z, 0.6f, 1e-3);
    EXPECT_FLOAT_EQ(extentOf(out, SurfacePart::Parapet).highest, 6.0f + kRoadLevel + kParapetHeight);
}
