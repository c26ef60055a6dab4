// Street features through the whole importer: crossings (nodes, and footway=crossing ways
// meeting carriageways) on the road vertices bit for bit, railways, pedestrian areas and car
// parks; then the osmnx files and the real San Francisco extract.
#include "osm/osm_import.h"

#include "osm_test_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <utility>

using namespace urbis;

namespace {

using test::findById;
using test::node;
using test::tag;
using test::way;
using test::writeOsm;

/// Every road vertex, by the bits of its coordinates.
std::set<std::pair<uint64_t, uint64_t>> roadVertices(const CityModel& city) {
    std::set<std::pair<uint64_t, uint64_t>> vertices;
    for (const Road& r : city.roads)
        for (const Vec2d p : r.centerline) vertices.insert({std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y)});
    return vertices;
}

/// How many crossings lie on a road vertex, bit for bit.
size_t crossingsOnRoadVertices(const CityModel& city) {
    const auto vertices = roadVertices(city);
    return size_t(std::count_if(city.crossings.begin(), city.crossings.end(), [&](const Crossing& c) {
        return vertices.contains({std::bit_cast<uint64_t>(c.position.x), std::bit_cast<uint64_t>(c.position.y)});
    }));
}

} // namespace

TEST(OsmStreetImport, CrossingsRailwaysAndPedestrianAreas) {
    const std::string body =
        node(1, 100, 100) + node(2, 200, 100) + node(3, 200, 200) + way(100, {1, 2, 3, 1}, tag("building", "yes")) +
        // A street with a zebra node (11) and a node (12) shared with a signalled footway=crossing way.
        node(10, 100, 500) + node(11, 700, 500, tag("highway", "crossing") + tag("crossing", "zebra")) +
        node(12, 1500, 500) + node(13, 2500, 500) +
        way(200, {10, 11, 12, 13}, tag("highway", "residential")) +
        node(14, 1500, 300) + node(15, 1500, 700) +
        way(201, {14, 12, 15}, tag("highway", "footway") + tag("footway", "crossing") + tag("crossing", "traffic_signals")) +
        // A footway=crossing way that meets only a footway makes no crossing; nor does crossing=no.
        node(16, 500, 900) + node(17, 600, 900) + node(18, 700, 900) +
        way(202, {16, 17}, tag("highway", "footway") + tag("footway", "crossing")) +
        way(203, {17, 18}, tag("highway", "footway")) +
        node(19, 900, 500, tag("highway", "crossing") + tag("crossing", "no")) +
        node(20, 40000, 500, tag("highway", "crossing")) + // outside the box
        // A tram line, an abandoned line, a pedestrian square and a mistagged unclosed one, a car park.
        node(30, 100, 1200) + node(31, 2500, 1200) + node(32, 100, 1300) + node(33, 2500, 1300) +
        way(300, {30, 31}, tag("railway", "tram") + tag("bridge", "yes") + tag("layer", "1")) +
        way(301, {32, 33}, tag("railway", "abandoned")) +
        node(40, 1000, 1500) + node(41, 1200, 1500) + node(42, 1200, 1700) + node(43, 1000, 1700) +
        way(400, {40, 41, 42, 43, 40},
            tag("highway", "pedestrian") + tag("area", "yes") + tag("surface", "paving_stones")) +
        way(401, {40, 41, 42}, tag("highway", "pedestrian") + tag("area", "yes")) +
        node(44, 2000, 1500) + node(45, 2200, 1500) + node(46, 2200, 1700) +
        way(402, {44, 45, 46, 44}, tag("amenity", "parking") + tag("surface", "asphalt") + tag("layer", "-1"));
    const CityModel city = importOsm(writeOsm("streets.osm", body), {});

    ASSERT_EQ(city.crossings.size(), 2u);
    const Crossing* zebra = findById(city.crossings, 11);
    const Crossing* signals = findById(city.crossings, 12);
    ASSERT_TRUE(zebra && signals);
    EXPECT_EQ(zebra->kind, CrossingKind::Zebra);
    EXPECT_EQ(signals->kind, CrossingKind::TrafficSignals);
    EXPECT_EQ(crossingsOnRoadVertices(city), 2u);
    EXPECT_EQ(countOf(city.dropped, "crossing_outside_bbox"), 1u);

    ASSERT_EQ(city.railways.size(), 1u);
    EXPECT_EQ(city.railways[0].kind, RailKind::Tram);
    EXPECT_TRUE(city.railways[0].embedded);
    EXPECT_TRUE(city.railways[0].bridge);
    EXPECT_EQ(city.railways[0].layer, 1);
    EXPECT_EQ(city.railways[0].centerline.size(), 2u);

    // Roads: the street, three footways and the unclosed "area"; the closed square is an area.
    EXPECT_EQ(city.roads.size(), 5u);
    EXPECT_FALSE(findById(city.roads, 400));
    ASSERT_EQ(city.areas.size(), 2u);
    const Area* square = findById(city.areas, 400);
    ASSERT_TRUE(square);
    EXPECT_EQ(square->kind, AreaKind::Pedestrian);
    EXPECT_EQ(square->surface, RoadSurface::PavingStones);
    const Area* parking = findById(city.areas, 402);
    ASSERT_TRUE(parking);
    EXPECT_EQ(parking->kind, AreaKind::Parking);
    EXPECT_EQ(parking->layer, -1);

    const nlohmann::json summary = inspectJson(city);
    EXPECT_EQ(summary["crossings"], 2);
    EXPECT_EQ(summary["railways"], 1);
    EXPECT_EQ(summary["areas"]["pedestrian"], 1);
    EXPECT_EQ(summary["areas"]["parking"], 1);
    EXPECT_EQ(summary["areas"]["park"], 0);
}

TEST(OsmStreetImport, OsmnxFiles) {
    // The village has no crossings or railways; West Oakland has two BART (subway) ways.
    const CityModel village = importOsm(URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm", {});
    EXPECT_TRUE(village.crossings.empty());
    EXPECT_TRUE(village.railways.empty());
    EXPECT_FALSE(village.roads.empty());
    const CityModel oakland = importOsm(URBIS_OSMNX_DATA "/West-Oakland.osm.bz2", {});
    std::cout << "West Oakland: " << inspectJson(oakland).dump() << "\n";
    ASSERT_FALSE(oakland.railways.empty());
    std::set<int64_t> railwayIds;
    for (const Railway& r : oakland.railways) {
        EXPECT_EQ(r.kind, RailKind::Subway);
        EXPECT_GE(r.centerline.size(), 2u);
        railwayIds.insert(r.osmId);
    }
    EXPECT_EQ(railwayIds.size() + countOf(oakland.dropped, "railway_outside_bbox"), 2u);
    for (const CityModel* city : {&village, &oakland})
        for (const Road& r : city->roads) {
            EXPECT_GT(r.width, 0.0f);
            EXPECT_GE(r.lanes, 1);
            EXPECT_GE(r.layer, -5);
            EXPECT_LE(r.layer, 5);
        }
}

TEST(OsmStreetImport, SanFranciscoStreets) {
    const std::string path = URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found, skipping";
    const CityModel city = importOsm(path, {});
    const nlohmann::json summary = inspectJson(city);
    std::cout << "San Francisco: crossings " << summary["crossings"] << ", railways " << summary["railways"]
              << ", areas " << summary["areas"].dump() << "\n";

    EXPECT_GT(city.crossings.size(), 1000u);
    const size_t onVertices = crossingsOnRoadVertices(city);
    std::cout << "  crossings on a road vertex, bit for bit: " << onVertices << " of " << city.crossings.size() << "\n";
    EXPECT_GE(double(onVertices), 0.95 * double(city.crossings.size()));

    // Muni's trams and cable cars (railway=tram / narrow_gauge), light rail, BART and Caltrain.
    EXPECT_GT(city.railways.size(), 0u);
    EXPECT_TRUE(std::any_of(city.railways.begin(), city.railways.end(),
                            [](const Railway& r) { return r.kind == RailKind::Tram && r.embedded; }));
    EXPECT_TRUE(std::any_of(city.railways.begin(), city.railways.end(), [](const Railway& r) { return r.tunnel; }));
    EXPECT_GT(std::count_if(city.roads.begin(), city.roads.end(), [](const Road& r) { return r.bridge; }), 0);
    EXPECT_GT(std::count_if(city.roads.begin(), city.roads.end(), [](const Road& r) { return r.tunnel; }), 0);
    EXPECT_GT(std::count_if(city.roads.begin(), city.roads.end(), [](const Road& r) { return r.sidewalk != Sidewalk::Unknown; }), 0);
    EXPECT_GT(std::count_if(city.roads.begin(), city.roads.end(), [](const Road& r) { return r.footway == FootwayKind::Sidewalk; }), 0);
    EXPECT_GT(summary["areas"]["pedestrian"].get<int>(), 0);
    EXPECT_GT(summary["areas"]["park"].get<int>(), 0);
    EXPECT_GT(summary["areas"]["parking"].get<int>(), 0);
}
