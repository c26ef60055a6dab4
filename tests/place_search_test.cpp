// Finding a named OSM feature (viewer/place_search.h): ranks, case, one place a name; and the names
// of an OSM file (osm/place_names.h): a node at its location, a way at the mean of its nodes.
#include "osm/place_names.h"
#include "osm_test_file.h"
#include "viewer/place_search.h"

#include <gtest/gtest.h>

namespace urbis {
namespace {

const std::vector<NamedPlace> kPlaces = {
    {"Market Street", 0, 0},  {"Ferry Building", 1, 1}, {"Ferry Plaza", 2, 2},
    {"Market Street", 3, 3},  {"The Ferry", 4, 4},       {"ferry", 5, 5},
};

TEST(PlaceSearch, EqualNamesFirstThenBeginningThenHolding) {
    EXPECT_EQ(findPlaces(kPlaces, "Ferry", 10), (std::vector<size_t>{5, 1, 2, 4}));
    EXPECT_EQ(findPlaces(kPlaces, "  FERRY b ", 10), (std::vector<size_t>{1}));
    EXPECT_EQ(findPlaces(kPlaces, "ferry", 2), (std::vector<size_t>{5, 1}));
}

TEST(PlaceSearch, OnePlaceANameAndNothingForNoQuery) {
    EXPECT_EQ(findPlaces(kPlaces, "street", 10), (std::vector<size_t>{0}));   // the first of the two ways
    EXPECT_TRUE(findPlaces(kPlaces, "", 10).empty());
    EXPECT_TRUE(findPlaces(kPlaces, "   ", 10).empty());
    EXPECT_TRUE(findPlaces(kPlaces, "Coit Tower", 10).empty());
}

TEST(PlaceNames, ANodeAtItsLocationAWayAtTheMeanOfItsNodes) {
    using namespace test;
    const std::string path = writeOsm("names.osm", node(1, 0, 0) + node(2, 1000, 0) + node(3, 1000, 1000) +
                                                       node(4, 0, 1000) + node(5, 500, 500, tag("name", "Fountain")) +
                                                       node(6, 100, 100, tag("amenity", "bench")) +
                                                       way(10, {1, 2, 3, 4, 1}, tag("building", "yes") + tag("name", "Hall")) +
                                                       way(11, {1, 2, 99}, tag("highway", "residential") + tag("name", "Lane")) +
                                                       way(12, {98, 99}, tag("name", "Nowhere")));
    const std::vector<NamedPlace> places = readPlaceNames(path);
    ASSERT_EQ(places.size(), 3u);
    EXPECT_EQ(places[0].name, "Fountain");
    EXPECT_NEAR(places[0].lon, 10.0005, 1e-9);
    EXPECT_NEAR(places[0].lat, 50.0005, 1e-9);
    EXPECT_EQ(places[1].name, "Hall");   // the closed ring's first node counted once: the square's centre
    EXPECT_NEAR(places[1].lon, 10.0005, 1e-9);
    EXPECT_NEAR(places[1].lat, 50.0005, 1e-9);
    EXPECT_EQ(places[2].name, "Lane");   // its missing node left out
    EXPECT_NEAR(places[2].lon, 10.0005, 1e-9);
    EXPECT_NEAR(places[2].lat, 50.0, 1e-9);
}

TEST(PlaceNames, ARelationAtTheMeanOfItsMemberWaysNodes) {
    using namespace test;
    // A forest mapped as a multipolygon whose outer way has no name of its own: found by the relation's name.
    const std::string path = writeOsm("relation_names.osm",
                                      node(1, 0, 0) + node(2, 1000, 0) + node(3, 1000, 1000) + node(4, 0, 1000) +
                                          way(10, {1, 2, 3, 4, 1}, tag("landuse", "forest")) +
                                          "<relation id='20' version='1'><member type='way' ref='10' role='outer'/>"
                                          "<member type='way' ref='77' role='outer'/>" +
                                          tag("type", "multipolygon") + tag("name", "Holz") + "</relation>\n" +
                                          "<relation id='21' version='1'><member type='way' ref='78' role='outer'/>" +
                                          tag("name", "Missing") + "</relation>\n");
    const std::vector<NamedPlace> places = readPlaceNames(path);
    ASSERT_EQ(places.size(), 1u);   // the relation whose member is not in the file is left out
    EXPECT_EQ(places[0].name, "Holz");
    EXPECT_NEAR(places[0].lon, 10.0005, 1e-9);
    EXPECT_NEAR(places[0].lat, 50.0005, 1e-9);
}

TEST(PlaceNames, AFileItCannotReadIsNamed) {
    try {
        readPlaceNames("/nonexistent/city.osm.pbf");
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/city.osm.pbf"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace urbis
