// Bridges on a terrain: a deck over a valley runs straight between the ground at its chain's two ends
// (not down into the valley), and on a level plateau lies as it does on the flat ground.
#include "citygen/city_on_terrain.h"
#include "citygen/city_scene.h"
#include "citygen/street_grades.h"
#include "geometry/scene_intersect.h"
#include "terrain_grids.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

/// The valley: rims at 30 m beyond |x| = 50, a V down to the floor at 0 m under the bridge's middle.
float valley(float x, float) { return 30.0f * std::min(1.0f, std::fabs(x) / 50.0f); }

/// A way along z = 0 from x0 to x1 (local y = 0), a point every 5 m.
Road way(double x0, double x1, bool bridge) {
    Road r;
    const int n = int(std::lround(std::fabs(x1 - x0) / 5.0));
    for (int i = 0; i <= n; ++i) r.centerline.push_back({x0 + (x1 - x0) * i / n, 0.0});
    r.width = 8.0f;
    r.sidewalk = Sidewalk::None;
    r.bridge = bridge;
    r.layer = bridge ? 1 : 0;
    return r;
}

/// Ground roads from x = -90 and 90 to a bridge over [-50, 50], drawn as two bridge ways that meet
/// at x = 0 running against each other (one chain), meshed and placed on `field` (none: flat ground).
CityMesh bridgeMesh(TerrainField& field) {
    CityModel city;
    city.roads = {way(-90, -50, false), way(-50, 0, true), way(50, 0, true), way(50, 90, false)};
    CityMesh mesh = meshCity(city);
    EXPECT_EQ(mesh.bridgeSpans.size(), 1u);
    if (field.record.nx > 0) {
        gradeStreets(field, mesh, smoothedHeights(field, kGradeRadius));
        placeCityOnTerrain(mesh, field);
    }
    return mesh;
}

Scene bridgeScene(TerrainField field) { return buildCityScene(bridgeMesh(field), {}, {}, field); }

/// The road's top straight down at (x, 0).
float roadTop(const Scene& scene, float x) {
    const SurfaceHit hit = intersectScene(scene.view(), Ray{{x, 200.0f, 0.0f}, {0, -1, 0}});
    EXPECT_TRUE(hit.valid() && hit.part == SurfacePart::Road) << x << ": part " << int(hit.part);
    return 200.0f - hit.t;
}

TEST(TerrainBridge, ADeckOverAValleyRunsStraightBetweenItsEnds) {
    const Scene scene = bridgeScene(test::fieldOf(valley));
    const float left = roadTop(scene, -49.0f), right = roadTop(scene, 49.0f);
    EXPECT_GT(left, 29.0f);
    EXPECT_GT(right, 29.0f);
    for (float x = -49.0f; x <= 49.0f; x += 2.0f) {
        const float chord = left + (x + 49.0f) / 98.0f * (right - left);
        EXPECT_NEAR(roadTop(scene, x), chord, 0.02f) << x;
    }
    EXPECT_GT(roadTop(scene, 0.0f), 25.0f);   // far above the valley's floor
}

TEST(TerrainBridge, ItsPiersStandOnTheGround) {
    TerrainField field = test::fieldOf(valley);
    const CityMesh mesh = bridgeMesh(field);
    size_t piers = 0;
    float lowest = INFINITY;   // the least height of a pier's vertex over the ground under it
    for (size_t i = 0; i < mesh.mesh.size(); ++i) {
        if (mesh.mesh.info[i].part != uint32_t(SurfacePart::Pier)) continue;
        ++piers;
        for (const Vec3f p : {mesh.mesh.triangles[i].p0, mesh.mesh.triangles[i].p1, mesh.mesh.triangles[i].p2})
            lowest = std::min(lowest, p.y - field.heightAt(p.x, p.z));
    }
    EXPECT_GT(piers, 0u);
    EXPECT_NEAR(lowest, 0.0f, 0.05f);   // feet on the ground: none sunk, none hanging
}

TEST(TerrainBridge, ADeckOnALevelPlateauLiesAsOnTheFlatGround) {
    const Scene flat = bridgeScene({});
    const Scene plateau = bridgeScene(test::fieldOf([](float, float) { return 30.0f; }));
    for (float x = -49.0f; x <= 49.0f; x += 7.0f) EXPECT_NEAR(roadTop(plateau, x), roadTop(flat, x) + 30.0f, 0.01f) << x;
    EXPECT_GT(roadTop(flat, 0.0f), 5.0f);   // the deck's clearance, kept over the plateau
}

} // namespace
} // namespace urbis
