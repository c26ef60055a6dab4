// Water on a terrain: each body at its own level (the lowest ground along its shore),
// the terrain carved below it as its bed, the shoreline where the terrain crosses the level, and the
// flat ground's plane open over the terrain's grid so that beds below y = 0 are seen.
#include "citygen/city_on_terrain.h"
#include "citygen/city_scene.h"
#include "citygen/water_on_terrain.h"
#include "geometry/scene_intersect.h"
#include "streets/street_levels.h"
#include "streets/water_depth.h"
#include "terrain_grids.h"
#include "water_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

using test::fieldOf;

/// `areas` meshed (no buildings) and placed on `field` with their water at its levels; the levels.
WaterLevels placeWater(CityMesh& mesh, TerrainField& field, const std::vector<Area>& areas) {
    CityModel city;
    city.areas = areas;
    mesh = meshCity(city);
    const WaterLevels levels = waterLevelsOn(mesh, field);
    carveWaterBeds(field, mesh, levels, WaterOptions{});
    placeCityOnTerrain(mesh, field, levels);
    return levels;
}

/// The first hit straight down from `y` at (x, z).
SurfaceHit downFrom(const SceneView& view, float x, float y, float z) {
    return intersectScene(view, Ray{{x, y, z}, {0, -1, 0}});
}

bool isWater(const Scene& scene, const SurfaceHit& hit) {
    return hit.valid() && scene.materials[hit.material].kind == MaterialKind::Water;
}

TEST(TerrainWater, ALakeLiesAtTheLowestGroundOfItsShoreOverTheCarvedTerrain) {
    // A bowl, 10 m at its centre; the pond's square (40 m) meets 12 m at its edges' middles, 14 m at its corners.
    auto bowl = [](float x, float z) { return 10.0f + 0.005f * (x * x + z * z); };
    TerrainField field = fieldOf(bowl);
    CityMesh mesh;
    const WaterLevels levels = placeWater(mesh, field, {test::squareArea(AreaKind::Water, 20)});
    ASSERT_EQ(levels.size(), 1u);
    const float level = levels.begin()->second.level;
    EXPECT_NEAR(level, 12.0f, 1e-4f);

    // Samples under the water lie below the level by the bank's profile; those outside are untouched.
    const WaterOptions options;
    for (uint32_t j = 0; j < field.record.nz; ++j)
        for (uint32_t i = 0; i < field.record.nx; ++i) {
            const float x = -100.0f + 2.0f * float(i), z = -100.0f + 2.0f * float(j);
            const float h = field.data[size_t(j) * field.record.nx + i];
            if (std::fabs(x) < 20.0f && std::fabs(z) < 20.0f) {
                const float shore = 20.0f - std::max(std::fabs(x), std::fabs(z));
                EXPECT_LE(h, level - waterBedDepth(shore, options) + 1e-4f) << x << "," << z;
            } else if (std::fabs(x) > 20.0f || std::fabs(z) > 20.0f) {
                EXPECT_EQ(h, bowl(x, z)) << x << "," << z;
            }
        }
    EXPECT_NEAR(field.heightAt(0, 0), level - options.maxDepth, 1e-4f);   // over a shelf from the shore

    // The surface lies flat at the level; the flat ground's bed is gone and its triangles uncounted.
    size_t surface = 0;
    for (size_t i = 0; i < mesh.mesh.size(); ++i) {
        if (mesh.mesh.info[i].part != uint32_t(SurfacePart::Water)) continue;
        ASSERT_EQ(mesh.materials[mesh.mesh.info[i].material].kind, MaterialKind::Water) << "a bed triangle is left";
        const Triangle& t = mesh.mesh.triangles[i];
        EXPECT_EQ(t.p0.y, level);
        EXPECT_EQ(t.p1.y, level);
        EXPECT_EQ(t.p2.y, level);
        ++surface;
    }
    EXPECT_EQ(mesh.trianglesByKind["water"], surface);

    // Straight down: the water at the level, then the terrain below it at least the bed's least depth
    // a sample spacing from the shore; beyond the shore, dry terrain above the level.
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SceneView view = scene.view();
    for (float x = -17.0f; x <= 17.0f; x += 1.7f)
        for (float z = -17.0f; z <= 17.0f; z += 1.7f) {
            const SurfaceHit water = downFrom(view, x, 50.0f, z);
            ASSERT_TRUE(isWater(scene, water)) << x << "," << z;
            EXPECT_NEAR(50.0f - water.t, level, 1e-4f);
            const SurfaceHit bed = downFrom(view, x, level - 1e-3f, z);
            ASSERT_TRUE(bed.valid());
            EXPECT_EQ(bed.kind, kPrimKindOf<TerrainRecord>);
            EXPECT_GE(bed.t, kMinBedDepth - 1e-3f - 1e-4f) << x << "," << z;
        }
    for (const float x : {-30.0f, -23.0f, 23.0f, 30.0f})
        for (const float z : {-30.0f, 0.0f, 23.0f}) {
            const SurfaceHit dry = downFrom(view, x, 50.0f, z);
            ASSERT_TRUE(dry.valid());
            EXPECT_EQ(dry.kind, kPrimKindOf<TerrainRecord>) << x << "," << z;
            EXPECT_GT(50.0f - dry.t, level) << x << "," << z;
        }
    // The shoreline: along z = 0 the terrain crosses the level within a sample spacing of the shore.
    for (float x = 0.0f; x <= 30.0f; x += 0.25f) {
        const float h = field.heightAt(x, 0.0f);
        if (x < 18.0f) {
            EXPECT_LT(h, level) << x;
        } else if (x > 22.0f) {
            EXPECT_GT(h, level) << x;
        }
    }
}

TEST(TerrainWater, AnOsmEleSetsTheLevel) {
    // The same pond in the bowl, tagged ele=13.5: its level, not its shore's lowest ground (12 m).
    auto bowl = [](float x, float z) { return 10.0f + 0.005f * (x * x + z * z); };
    TerrainField field = fieldOf(bowl);
    Area pond = test::squareArea(AreaKind::Water, 20);
    pond.ele = 13.5f;
    CityMesh mesh;
    const WaterLevels levels = placeWater(mesh, field, {pond});
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_EQ(levels.begin()->second.level, 13.5f);
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SurfaceHit water = downFrom(scene.view(), 0.0f, 50.0f, 0.0f);
    ASSERT_TRUE(isWater(scene, water));
    EXPECT_NEAR(50.0f - water.t, 13.5f, 1e-4f);
    EXPECT_NEAR(field.heightAt(0, 0), 13.5f - WaterOptions{}.maxDepth, 1e-4f);   // the bed below that level
}

TEST(TerrainWater, TheSeaLiesOverTheFlatGroundAndItsBedBelowItOnTheGrid) {
    // Flat land at 0 on the grid; the sea covers x < 0 far beyond it.
    TerrainField field = fieldOf([](float, float) { return 0.0f; });
    Area sea;
    sea.kind = AreaKind::Water;
    sea.polygon.outer = {{-400, -400}, {0, -400}, {0, 400}, {-400, 400}};
    CityMesh mesh;
    const WaterLevels levels = placeWater(mesh, field, {sea});
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_EQ(levels.begin()->second.level, kWaterLevel);
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SceneView view = scene.view();
    // On the grid the plane y = 0 is open: the bed is the terrain, a shelf out at the full depth.
    const SurfaceHit onGrid = downFrom(view, -50.0f, kWaterLevel - 1e-3f, 10.0f);
    ASSERT_TRUE(onGrid.valid());
    EXPECT_EQ(onGrid.kind, kPrimKindOf<TerrainRecord>);
    EXPECT_NEAR(kWaterLevel - 1e-3f - onGrid.t, kWaterLevel - WaterOptions{}.maxDepth, 1e-3f);
    // Beyond the grid the flat ground lies under the water, as without a terrain.
    ASSERT_TRUE(isWater(scene, downFrom(view, -300.0f, 10.0f, 0.0f)));
    const SurfaceHit offGrid = downFrom(view, -300.0f, kWaterLevel - 1e-3f, 0.0f);
    ASSERT_TRUE(offGrid.valid());
    EXPECT_EQ(offGrid.kind, kPrimKindOf<GroundRecord>);
    EXPECT_NEAR(offGrid.t, kWaterLevel - 1e-3f, 1e-5f);
}

} // namespace
} // namespace urbis
