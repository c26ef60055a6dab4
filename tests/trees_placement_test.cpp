// Where trees stand: on the real extracts (the Bavarian village, San Francisco, London) no placed
// tree stands on a carriageway, in a building or in water, checked by brute force over the model's
// roads, footprints and water areas (not through the placement's own grids); filled trees keep their
// clearance; woods and parks get filled; tree rows become trees; placement is deterministic; the
// forest beyond the city (a ForestRecord's cells) rings it and keeps out of its roads, buildings and water.
#include "nature/forest_records.h"
#include "nature/tree_placement.h"
#include "scene/forest_cells.h"
#include "model/polygon_ops.h"
#include "osm/osm_import.h"
#include "osm/tree_rows.h"
#include "osm_test_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace urbis;

namespace {

bool carriageway(HighwayClass h) {
    return h != HighwayClass::Footway && h != HighwayClass::Cycleway && h != HighwayClass::Path &&
           h != HighwayClass::Steps && h != HighwayClass::Track && h != HighwayClass::Pedestrian;
}

/// The least distance from `p` to a carriageway's edge (negative: on it), over every road segment.
double carriagewayMargin(const CityModel& city, Vec2d p) {
    double margin = INFINITY;
    for (const Road& r : city.roads) {
        if (r.tunnel || r.underground || !carriageway(r.highway)) continue;
        for (size_t i = 0; i + 1 < r.centerline.size(); ++i)
            margin = std::min(margin, distanceToSegment(p, r.centerline[i], r.centerline[i + 1]) - 0.5 * r.width);
    }
    return margin;
}

bool inAny(const CityModel& city, Vec2d p, bool water) {
    if (!water) {
        for (const Building& b : city.buildings)
            if (b.footprint.outer.size() >= 3 && contains(b.footprint, p)) return true;
        return false;
    }
    for (const Area& a : city.areas)
        if (a.kind == AreaKind::Water && contains(a.polygon, p)) return true;
    return false;
}

void expectTreesStandFree(const std::string& path, bool expectFilled) {
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found, skipping";
    const CityModel city = importOsm(path, ImportOptions{});
    std::map<std::string, uint64_t> dropped;
    const TreeOptions options;
    const std::vector<Tree> trees = placeTrees(city, options, dropped);
    size_t filled = 0;
    for (const Tree& t : trees) {
        const bool mapped = t.osmId != 0;
        filled += !mapped;
        // Filled trees keep the clearance and a sidewalk's allowance off carriageways; mapped ones their edge.
        const double margin = carriagewayMargin(city, t.position);
        EXPECT_GE(margin, mapped ? 0.0 : options.clearance + kTreeSidewalkAllowance - 1e-6)
            << path << ": tree " << t.osmId << " at " << t.position.x << ", " << t.position.y << " on a road";
        EXPECT_FALSE(inAny(city, t.position, false)) << path << ": tree " << t.osmId << " in a building";
        EXPECT_FALSE(inAny(city, t.position, true)) << path << ": tree " << t.osmId << " in water";
    }
    std::printf("%s: %zu mapped trees in the model, %zu placed (%zu filled in); dropped: on road %llu, in building %llu, in water %llu\n",
                path.c_str(), city.trees.size(), trees.size(), filled, (unsigned long long)dropped["tree_on_road"],
                (unsigned long long)dropped["tree_in_building"], (unsigned long long)dropped["tree_in_water"]);
    if (expectFilled) {
        EXPECT_GT(filled, 0u) << path << ": its parks and woods must be filled";
    }
    // Deterministic: the same model and options give the same trees.
    std::map<std::string, uint64_t> again;
    const std::vector<Tree> second = placeTrees(city, options, again);
    ASSERT_EQ(second.size(), trees.size());
    for (size_t i = 0; i < trees.size(); ++i) EXPECT_EQ(second[i].position.x, trees[i].position.x);
}

/// Calls f(model position) for every tree of `forests`, cell by cell (forestFoot).
template <typename F>
void forEachForestTree(const std::vector<ForestRecord>& forests, F&& f) {
    for (const ForestRecord& forest : forests)
        for (int32_t k = int32_t(std::floor(forest.z0 / forest.cell)); k <= int32_t(std::floor(forest.z1 / forest.cell)); ++k)
            for (int32_t i = int32_t(std::floor(forest.x0 / forest.cell)); i <= int32_t(std::floor(forest.x1 / forest.cell)); ++i) {
                HashStream rng;
                float x, z;
                if (forestFoot(forest, i, k, rng, x, z)) f(Vec2d{x, -z});
            }
}

/// The forest ring around the extract at `path` (its first 30 m, where the city is nearest): no tree
/// on a carriageway or its sidewalk, in a building or in water, by brute force over the model.
void expectForestStandsFree(const std::string& path) {
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found, skipping";
    const CityModel city = importOsm(path, ImportOptions{});
    TreeOptions options;
    options.outerForest = 30.0f;
    const std::vector<ForestRecord> forests = outerForestRecords(city, options, 0, 0);
    ASSERT_EQ(forests.size(), 4u);
    size_t trees = 0;
    forEachForestTree(forests, [&](Vec2d p) {
        ++trees;
        EXPECT_GE(carriagewayMargin(city, p), options.clearance + kTreeSidewalkAllowance - 1e-3)
            << path << ": a forest tree at " << p.x << ", " << p.y << " on a road";
        EXPECT_FALSE(inAny(city, p, false)) << path << ": a forest tree at " << p.x << ", " << p.y << " in a building";
        EXPECT_FALSE(inAny(city, p, true)) << path << ": a forest tree at " << p.x << ", " << p.y << " in water";
    });
    std::printf("%s: %zu trees in 30 m of forest around it\n", path.c_str(), trees);
    EXPECT_GT(trees, 500u);
}

std::string sharedData(const char* name) { return std::string(URBIS_SHARED_DATA) + "/" + name; }

} // namespace

TEST(TreePlacement, BavarianVillageTreesStandOnNoRoadBuildingOrWater) {
    expectTreesStandFree(std::string(URBIS_OSMNX_DATA) + "/planet_10.068,48.135_10.071,48.137.osm", false);
}

TEST(TreePlacement, SanFranciscoTreesStandOnNoRoadBuildingOrWater) {
    expectTreesStandFree(sharedData("sf_downtown_2023.osm.pbf"), true);
}

TEST(TreePlacement, LondonTreesStandOnNoRoadBuildingOrWater) {
    expectTreesStandFree(sharedData("london_city_2020.osm.pbf"), true);
}

TEST(TreePlacement, FillsAWoodAtItsDensityAroundARoadAndAPond) {
    // A 100 x 100 m wood crossed by a road, with a pond and a house in it.
    CityModel city;
    Area wood;
    wood.kind = AreaKind::Forest;
    wood.polygon.outer = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    city.areas.push_back(wood);
    Area pond;
    pond.kind = AreaKind::Water;
    pond.polygon.outer = {{60, 60}, {90, 60}, {90, 90}, {60, 90}};
    city.areas.push_back(pond);
    Road road;
    road.centerline = {{-10, 30}, {110, 30}};
    road.width = 6.0f;
    city.roads.push_back(road);
    Building house;
    house.footprint.outer = {{10, 60}, {30, 60}, {30, 80}, {10, 80}};
    city.buildings.push_back(house);
    TreeOptions options;
    options.forestDensity = 400.0f;  // a tree per 25 m^2
    std::map<std::string, uint64_t> dropped;
    const std::vector<Tree> trees = placeTrees(city, options, dropped);
    // Free ground: 10000 m^2 less the road's corridor (6 + 2 x 4 m), the pond's and the house's
    // (with 1 m clearance): about 10000 - 1400 - 1024 - 484 = 7092 m^2, so some 284 trees.
    EXPECT_NEAR(double(trees.size()), 284.0, 284.0 * 0.15);
    for (const Tree& t : trees) {
        EXPECT_GE(std::fabs(t.position.y - 30.0), 3.0 + kTreeSidewalkAllowance + options.clearance - 1e-9);
        EXPECT_FALSE(t.position.x > 59 && t.position.x < 91 && t.position.y > 59 && t.position.y < 91);
        EXPECT_FALSE(t.position.x > 9 && t.position.x < 31 && t.position.y > 59 && t.position.y < 81);
    }
    options.forestDensity = 0.0f;
    EXPECT_TRUE(placeTrees(city, options, dropped).empty()) << "density 0 fills nothing";
}

TEST(TreePlacement, MappedTreesOnARoadOrInABuildingAreDropped) {
    CityModel city;
    Road road;
    road.centerline = {{0, 0}, {100, 0}};
    road.width = 8.0f;
    city.roads.push_back(road);
    Building b;
    b.footprint.outer = {{0, 20}, {10, 20}, {10, 30}, {0, 30}};
    city.buildings.push_back(b);
    for (Vec2d p : {Vec2d{50, 1}, Vec2d{5, 25}, Vec2d{50, 6}}) {
        Tree t;
        t.osmId = 1;
        t.position = p;
        city.trees.push_back(t);
    }
    std::map<std::string, uint64_t> dropped;
    const std::vector<Tree> trees = placeTrees(city, TreeOptions{}, dropped);
    ASSERT_EQ(trees.size(), 1u) << "only the tree beside the road (on its sidewalk) stays";
    EXPECT_EQ(trees[0].position.y, 6.0);
    EXPECT_EQ(dropped["tree_on_road"], 1u);
    EXPECT_EQ(dropped["tree_in_building"], 1u);
}

TEST(TreePlacement, TreeRowsAreImportedAsTreesAlongThem) {
    // A row of about 86 m (0.0012 degrees of longitude at 50 N): trees 8 m apart, both ends included.
    // The import needs a building in the box; ids in order, nodes before ways.
    const std::string body = test::node(1, 100, 500) + test::node(2, 1300, 500) + test::node(5, 100, 100) +
                             test::node(6, 200, 100) + test::node(7, 200, 200) +
                             test::way(10, {1, 2}, test::tag("natural", "tree_row") + test::tag("leaf_type", "needleleaved")) +
                             test::way(100, {5, 6, 7, 5}, test::tag("building", "yes"));
    const CityModel city = importOsm(test::writeOsm("tree_row.osm", body), ImportOptions{});
    ASSERT_EQ(city.trees.size(), 12u);
    for (const Tree& t : city.trees) {
        EXPECT_EQ(t.osmId, 10);
        EXPECT_EQ(t.leafType, LeafType::Needleleaved);
    }
    const std::vector<LonLat> points = treeRowPoints({{10.0, 50.0}, {10.0, 50.001}}, 10.0);
    EXPECT_EQ(points.size(), 13u) << "111 m in pieces of at most 10 m";
}

TEST(TreePlacement, OuterForestRingsTheCityAndStaysOutOfIt) {
    CityModel city;
    Road road;
    road.centerline = {{0, 0}, {200, 0}};
    road.width = 8.0;
    city.roads.push_back(road);
    Building b;
    b.footprint.outer = {{50, 20}, {150, 20}, {150, 100}, {50, 100}};
    city.buildings.push_back(b);
    TreeOptions options;
    options.outerForest = 400.0f;
    const std::vector<ForestRecord> forests = outerForestRecords(city, options, 7, 3);
    ASSERT_EQ(forests.size(), 4u);
    // The city's extent: the box (0, 0)-(200, 100) grown by the road's half width, a sidewalk and the clearance.
    const double margin = 4.0 + kTreeSidewalkAllowance + options.clearance;
    uint64_t trees = 0;
    forEachForestTree(forests, [&](Vec2d p) {
        ++trees;
        EXPECT_FALSE(p.x > -margin && p.x < 200 + margin && p.y > -margin && p.y < 100 + margin)
            << "a tree inside the city's extent at " << p.x << ", " << p.y;
    });
    uint64_t counted = 0;
    for (const ForestRecord& f : forests) counted += forestTreeCount(f);
    EXPECT_EQ(trees, counted);
    const double ring = (200 + 2 * (margin + 400)) * (100 + 2 * (margin + 400)) - (200 + 2 * margin) * (100 + 2 * margin);
    const double expected = ring * options.outerForestDensity / 10000.0;
    EXPECT_NEAR(double(trees), expected, 4.0 * std::sqrt(expected));
    options.outerForest = 0.0f;
    EXPECT_TRUE(outerForestRecords(city, options, 7, 3).empty());
}

TEST(TreePlacement, BavarianVillageForestStandsOnNoRoadBuildingOrWater) {
    expectForestStandsFree(std::string(URBIS_OSMNX_DATA) + "/planet_10.068,48.135_10.071,48.137.osm");
}

TEST(TreePlacement, SanFranciscoForestStandsOnNoRoadBuildingOrWater) {
    expectForestStandsFree(sharedData("sf_downtown_2023.osm.pbf"));
}

TEST(TreePlacement, LondonForestStandsOnNoRoadBuildingOrWater) {
    expectForestStandsFree(sharedData("london_city_2020.osm.pbf"));
}
