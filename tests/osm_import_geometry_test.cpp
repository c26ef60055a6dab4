// Small hand-written .osm files through the whole importer: multipolygon holes, parts
// replacing outlines, underground drops, ring cleaning and orientation, repairs and drops,
// road clipping.
#include "model/polygon_ops.h"
#include "osm/osm_import.h"

#include "osm_test_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace urbis;

namespace {

using test::node;
using test::tag;
using test::way;
using test::writeOsm;

const Building* findBuilding(const CityModel& city, int64_t osmId) { return test::findById(city.buildings, osmId); }

} // namespace

TEST(OsmImportGeometry, MultipolygonBuildingKeepsItsHole) {
    // Outer 100 x 100 µdeg square (about 7.2 x 11.1 m) drawn clockwise in two ways, a
    // 20 x 20 µdeg courtyard; the relation carries the building tags.
    const std::string body =
        node(1, 1000, 1000) + node(2, 1000, 1100) + node(3, 1100, 1100) + node(4, 1100, 1000) +
        node(5, 1040, 1040) + node(6, 1060, 1040) + node(7, 1060, 1060) + node(8, 1040, 1060) +
        way(10, {1, 2, 3}, "") + way(11, {3, 4, 1}, "") + way(12, {5, 6, 7, 8, 5}, "") +
        "<relation id='20' version='1'><member type='way' ref='10' role='outer'/>"
        "<member type='way' ref='11' role='outer'/><member type='way' ref='12' role='inner'/>" +
        tag("type", "multipolygon") + tag("building", "apartments") + tag("building:levels", "5") + "</relation>\n";
    const CityModel city = importOsm(writeOsm("multipolygon.osm", body), {});
    ASSERT_EQ(city.buildings.size(), 1u);
    const Building& b = city.buildings[0];
    EXPECT_EQ(b.osmId, -20);
    EXPECT_EQ(b.type, BuildingType::Apartments);
    EXPECT_FLOAT_EQ(b.height, 15.0f);
    ASSERT_EQ(b.footprint.holes.size(), 1u);
    EXPECT_EQ(b.footprint.outer.size(), 4u); // closing point removed
    EXPECT_EQ(b.footprint.holes[0].size(), 4u);
    EXPECT_GT(signedArea(b.footprint.outer), 0.0); // counter-clockwise
    EXPECT_LT(signedArea(b.footprint.holes[0]), 0.0); // clockwise
    const double outer = signedArea(b.footprint.outer), hole = -signedArea(b.footprint.holes[0]);
    EXPECT_NEAR(hole / outer, 0.04, 1e-3);
    EXPECT_NEAR(area(b.footprint), outer - hole, 1e-6);
    EXPECT_NEAR(outer, 7.1695 * 11.1231, 0.1); // 1e-4 deg of lon and of lat at 50 N, in m
}

TEST(OsmImportGeometry, PartsReplaceTheirOutline) {
    // Outline 1 with two parts inside it; outline 2 has none and stays.
    const std::string body =
        node(1, 1000, 1000) + node(2, 1200, 1000) + node(3, 1200, 1100) + node(4, 1000, 1100) +
        node(5, 1010, 1010) + node(6, 1090, 1010) + node(7, 1090, 1090) + node(8, 1010, 1090) +
        node(9, 1110, 1010) + node(10, 1190, 1010) + node(11, 1190, 1090) + node(12, 1110, 1090) +
        node(13, 2000, 1000) + node(14, 2100, 1000) + node(15, 2100, 1100) + node(16, 2000, 1100) +
        way(100, {1, 2, 3, 4, 1}, tag("building", "yes") + tag("height", "30")) +
        way(101, {5, 6, 7, 8, 5}, tag("building:part", "yes") + tag("height", "30")) +
        way(102, {9, 10, 11, 12, 9}, tag("building:part", "yes") + tag("height", "12") + tag("min_height", "3")) +
        way(103, {13, 14, 15, 16, 13}, tag("building", "house"));
    const CityModel city = importOsm(writeOsm("parts.osm", body), {});
    EXPECT_EQ(city.buildings.size(), 3u);
    EXPECT_EQ(city.buildingParts(), 2u);
    EXPECT_EQ(findBuilding(city, 100), nullptr);
    ASSERT_NE(findBuilding(city, 102), nullptr);
    EXPECT_TRUE(findBuilding(city, 102)->isPart);
    EXPECT_FLOAT_EQ(findBuilding(city, 102)->minHeight, 3.0f);
    ASSERT_NE(findBuilding(city, 103), nullptr);
    EXPECT_FALSE(findBuilding(city, 103)->isPart);
    EXPECT_EQ(countOf(city.dropped, "replaced_by_parts"), 1u);
}

TEST(OsmImportGeometry, UndergroundBuildingsAreDroppedAndCounted) {
    // A house, and a metro station hall beside it tagged as San Francisco's are.
    const std::string body =
        node(1, 1000, 1000) + node(2, 1100, 1000) + node(3, 1100, 1100) + node(4, 1000, 1100) +
        node(5, 1300, 1000) + node(6, 1600, 1000) + node(7, 1600, 1200) + node(8, 1300, 1200) +
        way(100, {1, 2, 3, 4, 1}, tag("building", "house")) +
        way(101, {5, 6, 7, 8, 5}, tag("building", "train_station") + tag("location", "underground") +
                                      tag("layer", "-1") + tag("level", "-3;-2;-1"));
    const CityModel city = importOsm(writeOsm("underground.osm", body), {});
    ASSERT_EQ(city.buildings.size(), 1u);
    EXPECT_EQ(city.buildings[0].osmId, 100);
    EXPECT_EQ(countOf(city.dropped, "underground"), 1u);
}

TEST(OsmImportGeometry, UndergroundPartLeavesItsOutlineAndBridgesStay) {
    // Outline 100 over a basement garage part (level=-1), which replaces nothing; part 102,
    // a bridge between buildings from the third storey up, stands.
    const std::string body =
        node(1, 1000, 1000) + node(2, 1200, 1000) + node(3, 1200, 1100) + node(4, 1000, 1100) +
        node(5, 1010, 1010) + node(6, 1190, 1010) + node(7, 1190, 1090) + node(8, 1010, 1090) +
        node(9, 2000, 1000) + node(10, 2100, 1000) + node(11, 2100, 1030) + node(12, 2000, 1030) +
        way(100, {1, 2, 3, 4, 1}, tag("building", "apartments")) +
        way(101, {5, 6, 7, 8, 5}, tag("building:part", "garages") + tag("level", "-1")) +
        way(102, {9, 10, 11, 12, 9}, tag("building:part", "yes") + tag("building:min_level", "3") +
                                         tag("building:levels", "4"));
    const CityModel city = importOsm(writeOsm("underground_part.osm", body), {});
    ASSERT_EQ(city.buildings.size(), 2u);
    ASSERT_NE(findBuilding(city, 100), nullptr);
    ASSERT_NE(findBuilding(city, 102), nullptr);
    EXPECT_GT(findBuilding(city, 102)->minHeight, 0.0f);
    EXPECT_EQ(countOf(city.dropped, "part_underground"), 1u);
    EXPECT_FALSE(city.dropped.contains("underground"));
}

TEST(OsmImportGeometry, RingsAreCleanedRepairedOrDropped) {
    const std::string body =
        // 200: drawn clockwise, with a doubled node -> cleaned, turned counter-clockwise.
        node(1, 1000, 1000) + node(2, 1000, 1100) + node(3, 1100, 1100) + node(4, 1100, 1000) +
        way(200, {1, 2, 2, 3, 4, 1}, tag("building", "yes")) +
        // 201: a bow tie -> GEOS makes it valid (two triangles), the larger is kept.
        node(5, 2000, 1000) + node(6, 2100, 1100) + node(7, 2100, 1000) + node(8, 2000, 1150) +
        way(201, {5, 6, 7, 8, 5}, tag("building", "yes")) +
        // 202: a 0.5 x 0.5 m hut -> too small.
        node(9, 1500, 1500) + node(10, 1507, 1500) + node(11, 1507, 1504) + node(12, 1500, 1504) +
        way(202, {9, 10, 11, 12, 9}, tag("building", "hut")) +
        // 203: all nodes on a line -> degenerate; 204: not closed; 205: a missing node.
        way(203, {1, 2, 1}, tag("building", "yes")) + way(204, {1, 2, 3}, tag("building", "yes")) +
        way(205, {1, 2, 99, 1}, tag("building", "yes")) +
        // 206: centroid outside the bounds.
        node(13, 9000, 1000) + node(14, 9100, 1000) + node(15, 9100, 1100) +
        way(206, {13, 14, 15, 13}, tag("building", "yes")) +
        // 207: a bad height tag: kept with an estimated height (no tagged neighbours: the table), and counted.
        node(16, 500, 500) + node(17, 600, 500) + node(18, 600, 600) +
        way(207, {16, 17, 18, 16}, tag("building", "yes") + tag("height", "tall"));
    const CityModel city = importOsm(writeOsm("rings.osm", body), {});
    ASSERT_NE(findBuilding(city, 200), nullptr);
    const Ring& cleaned = findBuilding(city, 200)->footprint.outer;
    EXPECT_EQ(cleaned.size(), 4u);
    EXPECT_GT(signedArea(cleaned), 0.0);
    ASSERT_NE(findBuilding(city, 201), nullptr);
    EXPECT_EQ(findBuilding(city, 201)->footprint.outer.size(), 3u);
    EXPECT_EQ(countOf(city.repaired, "made_valid"), 1u);
    EXPECT_EQ(osmRefName(city.repaired.at("made_valid").ids.at(0)), "w201");
    EXPECT_EQ(findBuilding(city, 202), nullptr);
    EXPECT_EQ(countOf(city.dropped, "too_small"), 1u);
    EXPECT_EQ(osmRefName(city.dropped.at("too_small").ids.at(0)), "w202");
    EXPECT_EQ(countOf(city.dropped, "degenerate_footprint"), 1u);
    EXPECT_EQ(countOf(city.dropped, "unclosed_way"), 1u);
    EXPECT_EQ(countOf(city.dropped, "incomplete_geometry"), 1u);
    EXPECT_EQ(countOf(city.dropped, "outside_bbox"), 1u);
    ASSERT_NE(findBuilding(city, 207), nullptr);
    EXPECT_EQ(findBuilding(city, 207)->heightSource, HeightSource::TypeTable);
    EXPECT_EQ(countOf(city.repaired, "bad_height_tag"), 1u);
    EXPECT_EQ(countOf(city.dropped, "bad_height_tag"), 0u) << "a kept building is not dropped";
    EXPECT_EQ(city.buildings.size(), 3u);
}

TEST(OsmImportGeometry, RoadsAreClippedLampsAndTreesCropped) {
    // A road from inside the box (lon 10.001) to far east (10.01); the box ends at 10.003.
    const std::string body =
        node(1, 1000, 1000) + node(2, 1100, 1000) + node(3, 1100, 1100) +
        way(100, {1, 2, 3, 1}, tag("building", "yes")) +
        node(4, 1000, 500) + node(5, 10000, 500) + node(6, 20000, 500) + node(7, 20000, 900) +
        way(300, {4, 5}, tag("highway", "residential") + tag("lanes", "2")) +
        way(301, {6, 7}, tag("highway", "footway")) +
        node(8, 1500, 1500, tag("highway", "street_lamp")) + node(9, 1600, 1500, tag("natural", "tree")) +
        node(10, 30000, 1500, tag("natural", "tree"));
    ImportOptions options;
    const CityModel city = importOsm(writeOsm("roads.osm", body), options);
    ASSERT_EQ(city.roads.size(), 1u);
    const Road& road = city.roads[0];
    ASSERT_EQ(road.centerline.size(), 2u);
    const double kept = road.centerline[1].x - road.centerline[0].x;
    EXPECT_NEAR(kept, 2000e-6 * 111319.5 * std::cos(50.0 * 3.14159265 / 180.0), 1.0); // 10.001 -> 10.003
    EXPECT_EQ(countOf(city.dropped, "road_outside_bbox"), 1u);
    EXPECT_EQ(city.lamps.size(), 1u);
    EXPECT_EQ(city.trees.size(), 1u);
    EXPECT_EQ(countOf(city.dropped, "tree_outside_bbox"), 1u);
    EXPECT_EQ(osmRefName(city.dropped.at("tree_outside_bbox").ids.at(0)), "n10");
    EXPECT_TRUE(city.origin.valid);
    EXPECT_NEAR(city.origin.lat, 50.001, 1e-9);
    EXPECT_NEAR(city.origin.lon, 10.0015, 1e-9);
    EXPECT_EQ(city.source, "roads.osm");
}

TEST(OsmImportGeometry, BboxOptionOverridesTheHeaderBox) {
    const std::string village = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";
    const CityModel whole = importOsm(village, {});
    ImportOptions options;
    options.bbox = std::array<double, 4>{10.068, 48.135, 10.0695, 48.137}; // the western half
    const CityModel west = importOsm(village, options);
    EXPECT_LT(west.buildings.size(), whole.buildings.size());
    EXPECT_GT(west.buildings.size(), 0u);
    EXPECT_NEAR(west.origin.lon, 10.06875, 1e-9);
    EXPECT_NEAR(whole.origin.lon, 10.0695, 1e-9);
    for (const Building& b : west.buildings) EXPECT_LT(centroid(b.footprint.outer).x, 60.0); // box edge + slack
}
