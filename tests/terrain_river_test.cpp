// Rivers mapped only as lines on a terrain: the ribbon's surface falls along the line in its flow
// direction (the OSM way's), never rising, at or below the ground along it; the terrain is carved
// under it; a line drawn uphill keeps the level of its start; the banks rise from the water no
// steeper than the bank slope; the generated city's river is such a line.
#include "citygen/city_on_terrain.h"
#include "citygen/city_scene.h"
#include "citygen/city_terrain.h"
#include "layout/city_layout.h"
#include "layout/river.h"
#include "citygen/water_on_terrain.h"
#include "geometry/scene_intersect.h"
#include "streets/water_depth.h"
#include "terrain_grids.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

/// Falls 5 cm a metre eastwards with bumps of 1 m every 19 m, and rises to both sides of z = 0.
float ground(float x, float z) { return 20.0f - 0.05f * x + std::sin(x / 3.0f) + 0.02f * z * z; }

TerrainField slope() { return test::fieldOf(ground); }

/// A stream 3 m wide along z = 0 from x = `from` to x = `to` (its flow), drawn and placed on `field`.
WaterLevels placeStream(CityMesh& mesh, TerrainField& field, double from, double to) {
    Area stream;
    stream.kind = AreaKind::Water;
    stream.polygon.outer = {{-80, -1.5}, {80, -1.5}, {80, 1.5}, {-80, 1.5}};
    stream.flowLine = {{from, 0}, {to, 0}};
    CityModel city;
    city.areas = {stream};
    mesh = meshCity(city);
    EXPECT_EQ(mesh.waterFlows.size(), 1u);
    const WaterLevels levels = waterLevelsOn(mesh, field);
    carveRiverBanks(field, mesh, levels, WaterOptions{});
    carveWaterBeds(field, mesh, levels, WaterOptions{});
    placeCityOnTerrain(mesh, field, levels);
    return levels;
}

TEST(TerrainRiver, AStreamFallsAlongItsLineAndNeverRises) {
    const TerrainField natural = slope();
    TerrainField field = natural;
    CityMesh mesh;
    const WaterLevels levels = placeStream(mesh, field, -80, 80);
    ASSERT_EQ(levels.size(), 1u);
    const WaterLevel& river = levels.begin()->second;
    ASSERT_GT(river.line.size(), 80u) << "a point every half sample spacing";
    for (size_t i = 0; i < river.line.size(); ++i) {
        const Vec2d p = river.line[i];
        EXPECT_LE(river.heights[i], natural.heightAt(float(p.x), float(p.y)) + 1e-4f) << p.x;   // at or below the ground
        if (i > 0) {
            EXPECT_LE(river.heights[i], river.heights[i - 1]) << p.x;   // never rising
        }
    }
    EXPECT_GT(river.heights.front() - river.heights.back(), 6.0f) << "it falls with the slope";

    // Straight down: the water's surface, within 12 cm of the profile (its triangles are split where
    // their edges' midpoints or centres lie over 5 cm off it, and a kink between them may leave ~10 cm)
    // and not rising eastwards by more than 2 cm, then the carved terrain below it.
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SceneView view = scene.view();
    float before = INFINITY;
    for (float x = -78.0f; x <= 78.0f; x += 0.5f) {
        const SurfaceHit water = intersectScene(view, Ray{{x, 100.0f, 0.3f}, {0, -1, 0}});
        ASSERT_TRUE(water.valid() && scene.materials[water.material].kind == MaterialKind::Water) << x;
        const float surface = 100.0f - water.t;
        EXPECT_NEAR(surface, river.at(x, 0.3f), 0.12f) << x;
        EXPECT_LE(surface, before + 0.02f) << x;
        before = surface;
        const SurfaceHit bed = intersectScene(view, Ray{{x, surface - 1e-3f, 0.3f}, {0, -1, 0}});
        ASSERT_TRUE(bed.valid()) << x;
        EXPECT_EQ(bed.kind, kPrimKindOf<TerrainRecord>) << x;
        EXPECT_GE(bed.t, kMinBedDepth - 0.12f) << x;
    }
}

TEST(TerrainRiver, ALineDrawnUphillKeepsTheLevelOfItsStart) {
    TerrainField field = slope();
    CityMesh mesh;
    const WaterLevels levels = placeStream(mesh, field, 80, -80);
    const WaterLevel& river = levels.begin()->second;
    ASSERT_FALSE(river.line.empty());
    EXPECT_LE(river.heights.back(), ground(80, 0) + 1e-3f);
    // Where the ground is highest, the water lies metres below it, in a carved trench.
    EXPECT_LT(river.at(-78.0f, 0.0f), ground(-78.0f, 0.0f) - 6.0f);
    EXPECT_LT(field.heightAt(-78.0f, 0.0f), river.at(-78.0f, 0.0f));
}

TEST(TerrainRiver, ItsBanksRiseNoSteeperThanTheBankSlope) {
    // Drawn uphill, the stream keeps its start's level and runs metres below the ground westwards:
    // the ground beside it falls to it at the bank slope (a valley, not a trench with walls), and
    // ground already below that slope is not touched.
    const TerrainField natural = slope();
    TerrainField field = natural;
    CityMesh mesh;
    const WaterLevels levels = placeStream(mesh, field, 80, -80);
    const WaterLevel& river = levels.begin()->second;
    const float bankSlope = WaterOptions{}.bankSlope, lowest = river.level;
    size_t carved = 0;
    for (float x = -80.0f; x <= 80.0f; x += 2.0f)
        for (float z = 2.0f; z <= 98.0f; z += 2.0f)
            for (const float side : {-z, z}) {
                // Sample (x, side); the samples under the water lie on z = 0, at the surface there.
                const float h = field.heightAt(x, side), h0 = natural.heightAt(x, side);
                EXPECT_LE(h, std::min(h0, river.at(x, 0.0f) + bankSlope * z) + 1e-3f) << x << "," << side;
                if (h0 <= lowest + bankSlope * z) {
                    EXPECT_EQ(h, h0) << x << "," << side;
                }
                carved += h < h0;
            }
    EXPECT_GT(carved, 500u);
}

TEST(TerrainRiver, TheGeneratedRiverFallsEastwardBetweenBanksOnFbmHills) {
    LayoutParams params;
    params.buildings = 800;
    const CityModel city = generateCity(params);
    const River river = River::generate(params.seed);
    const Area* water = nullptr;
    for (const Area& a : city.areas)
        if (a.kind == AreaKind::Water) water = &a;
    ASSERT_NE(water, nullptr);
    ASSERT_GE(water->flowLine.size(), 2u);
    EXPECT_LT(water->flowLine.front().x, water->flowLine.back().x) << "it flows west to east";
    for (const Vec2d p : water->flowLine) EXPECT_DOUBLE_EQ(p.y, river.middleAt(p.x));
    const double east = water->flowLine.back().x;

    // With and without banks (a bank slope of 1000: walls): the banks must be what keeps the ground
    // beside the water within the slope, so the test fails without them.
    TerrainParams hills;
    hills.kind = "fbm";
    auto placed = [&](float bankSlope, float& widestRise) {
        CityMesh mesh = meshCity(city);
        WaterOptions options;
        options.bankSlope = bankSlope;
        const TerrainField field = cityTerrainOf(hills, GeoOrigin{}, mesh, options);
        const float slopeRise = WaterOptions{}.bankSlope, cell = field.record.cell;
        widestRise = 0;   // the most the ground beside the water rises above the bank slope
        float before = INFINITY;
        for (double x = -east + 40; x <= east - 40; x += 5) {
            // The bed in the middle lies max_depth below the surface (the middle is farther than a
            // shelf from the shore), falling eastwards (bilinear between samples: 0.5 m).
            const float bed = field.heightAt(float(x), float(-river.middleAt(x)));
            EXPECT_LE(bed, before + 0.5f) << x;
            before = std::min(before, bed);
            const float surface = bed + options.maxDepth;
            const auto [south, north] = river.across(x);
            for (double d = 5; d <= 120; d += 5)
                for (const double y : {north + d, south - d}) {
                    const float allowed = surface + slopeRise * float(d + 2 * cell) * 1.09f + 1.0f;
                    widestRise = std::max(widestRise, field.heightAt(float(x), float(-y)) - allowed);
                }
        }
    };
    float withBanks = 0, withWalls = 0;
    placed(WaterOptions{}.bankSlope, withBanks);
    placed(1000.0f, withWalls);
    EXPECT_LE(withBanks, 0.0f) << "the ground beside the river rises no steeper than the bank slope";
    EXPECT_GT(withWalls, 5.0f) << "these hills would stand as walls over the river without banks";
}

TEST(TerrainRiver, AnAreaCoveringTheLineWins) {
    // A lake (60 m square) over the middle of a stream's ribbon: the lake is drawn whole, the ribbon
    // only outside it.
    Area stream;
    stream.kind = AreaKind::Water;
    stream.polygon.outer = {{-80, -1.5}, {80, -1.5}, {80, 1.5}, {-80, 1.5}};
    stream.flowLine = {{-80, 0}, {80, 0}};
    Area lake;
    lake.kind = AreaKind::Water;
    lake.polygon.outer = {{-30, -30}, {30, -30}, {30, 30}, {-30, 30}};
    CityModel city;
    city.areas = {stream, lake};
    const CityMesh mesh = meshCity(city);
    const Scene scene = buildCityScene(mesh);
    const SceneView view = scene.view();
    auto objectAt = [&](float x, float z) {
        const SurfaceHit hit = intersectScene(view, Ray{{x, 10.0f, z}, {0, -1, 0}});
        EXPECT_TRUE(hit.valid() && scene.materials[hit.material].kind == MaterialKind::Water) << x << "," << z;
        return hit.object;
    };
    const uint32_t lakeObject = objectAt(0, 20);
    for (const float x : {-25.0f, 0.0f, 25.0f}) EXPECT_EQ(objectAt(x, 0.5f), lakeObject) << x;
    for (const float x : {-60.0f, 60.0f}) EXPECT_NE(objectAt(x, 0.5f), lakeObject) << x;
    size_t waterTriangles = 0;   // one surface over each point: no triangle of the ribbon inside the lake
    for (size_t i = 0; i < mesh.mesh.size(); ++i) {
        const Triangle& t = mesh.mesh.triangles[i];
        if (mesh.materials[mesh.mesh.info[i].material].kind != MaterialKind::Water || mesh.mesh.info[i].object == lakeObject) continue;
        const float cx = (t.p0.x + t.p1.x + t.p2.x) / 3.0f;
        EXPECT_GT(std::fabs(cx), 29.9f) << cx;
        ++waterTriangles;
    }
    EXPECT_GT(waterTriangles, 0u);
}

} // namespace
} // namespace urbis
