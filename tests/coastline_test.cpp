// natural=coastline closed against the box into sea polygons (osm/coastline.h): synthetic coasts
// whose sea is known exactly (areas to 1e-6 m^2), broken ones repaired or left out with a warning,
// and the real extract of San Francisco, whose box holds a stretch of the bay.
#include "model/polygon_ops.h"
#include "osm/coastline.h"
#include "osm/osm_import.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace urbis;

namespace {

constexpr Vec2d kMin{0, 0}, kMax{100, 100};

double seaArea(const SeaPolygons& s) {
    double a = 0;
    for (const Polygon& p : s.sea) a += area(p);
    return a;
}

} // namespace

TEST(Coastline, LandOnTheLeftSeaOnTheRight) {
    // Eastwards: land to the north, the sea the box's southern half.
    const SeaPolygons south = seaPolygons({{1, {{-10, 50}, {110, 50}}}}, kMin, kMax);
    ASSERT_EQ(south.sea.size(), 1u);
    EXPECT_NEAR(seaArea(south), 5000.0, 1e-6);
    EXPECT_LT(centroid(south.sea[0].outer).y, 50.0);
    EXPECT_GT(signedArea(south.sea[0].outer), 0.0) << "counter-clockwise";
    EXPECT_TRUE(south.warnings.empty());
    // Westwards: the northern half.
    const SeaPolygons north = seaPolygons({{1, {{110, 50}, {-10, 50}}}}, kMin, kMax);
    EXPECT_NEAR(seaArea(north), 5000.0, 1e-6);
    EXPECT_GT(centroid(north.sea[0].outer).y, 50.0);
    // South then east, turning a corner of the land: the north-east quarter is land.
    const SeaPolygons corner = seaPolygons({{1, {{50, 130}, {50, 50}, {130, 50}}}}, kMin, kMax);
    EXPECT_NEAR(seaArea(corner), 7500.0, 1e-6);
    EXPECT_TRUE(seaPolygons({}, kMin, kMax).sea.empty()) << "no coastline, no sea";
}

TEST(Coastline, WaysAreJoinedEndToEndInAnyOrder) {
    // The coast of the first test in three ways, listed out of order.
    const SeaPolygons s = seaPolygons({{3, {{70, 50}, {110, 50}}}, {1, {{-10, 50}, {30, 50}}}, {2, {{30, 50}, {70, 50}}}},
                                      kMin, kMax);
    ASSERT_EQ(s.sea.size(), 1u);
    EXPECT_NEAR(seaArea(s), 5000.0, 1e-6);
    EXPECT_TRUE(s.warnings.empty());
}

TEST(Coastline, IslandsAreHolesAndABoxWithOnlyAnIslandIsSea) {
    const std::vector<Vec2d> island = {{40, 40}, {60, 40}, {60, 60}, {40, 60}, {40, 40}};   // counter-clockwise: land inside
    const SeaPolygons s = seaPolygons({{7, island}}, kMin, kMax);
    ASSERT_EQ(s.sea.size(), 1u);
    ASSERT_EQ(s.sea[0].holes.size(), 1u);
    EXPECT_NEAR(seaArea(s), 10000.0 - 400.0, 1e-6);
    // The island off a coast: the southern half less the island.
    const std::vector<Vec2d> small = {{10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}};
    EXPECT_NEAR(seaArea(seaPolygons({{1, {{-10, 50}, {110, 50}}}, {7, small}}, kMin, kMax)), 5000.0 - 100.0, 1e-6);
    // A clockwise ring: a sea inside land (a lagoon), the rest of the box land.
    const std::vector<Vec2d> lagoon(island.rbegin(), island.rend());
    EXPECT_NEAR(seaArea(seaPolygons({{8, lagoon}}, kMin, kMax)), 400.0, 1e-6);
}

TEST(Coastline, AChainEndingInsideTheBoxIsCarriedToTheNearestEdgeWithAWarning) {
    // Broken off 40 m short of the east edge: carried east along y = 50.
    const SeaPolygons s = seaPolygons({{42, {{-10, 50}, {60, 50}}}}, kMin, kMax);
    ASSERT_EQ(s.sea.size(), 1u);
    EXPECT_NEAR(seaArea(s), 5000.0, 1e-6);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("w42"), std::string::npos) << s.warnings[0];
    EXPECT_NE(s.warnings[0].find("40 m"), std::string::npos) << s.warnings[0];
    EXPECT_EQ(s.extendedWays, std::vector<int64_t>{42});
}

TEST(Coastline, PiecesThatCannotCloseAreLeftOutWithAWarning) {
    // Two coasts both with land to their north: the southern one closes (its sea south of y = 30);
    // the northern one's sea would need the land between them: left out, named.
    const SeaPolygons s = seaPolygons({{1, {{-10, 30}, {110, 30}}}, {2, {{-10, 70}, {110, 70}}}}, kMin, kMax);
    ASSERT_EQ(s.sea.size(), 1u);
    EXPECT_NEAR(seaArea(s), 3000.0, 1e-6);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("w2"), std::string::npos) << s.warnings[0];
    EXPECT_EQ(s.droppedWays, std::vector<int64_t>{2});
}

// Downtown San Francisco's box reaches the bay east of the Embarcadero: its coastline closes into
// sea at the box's north-east, and the water there is deep enough to be seen (checked by the render).
TEST(Coastline, SanFranciscoHasTheBay) {
    const std::string path = std::string(URBIS_SHARED_DATA) + "/sf_downtown_2023.osm.pbf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path << " (the shared data folder is absent)";
    const CityModel city = importOsm(path, ImportOptions{});
    double sea = 0;
    Vec2d weighted{0, 0};
    for (const Area& a : city.areas)
        if (a.kind == AreaKind::Water && a.osmId == 0) {
            const double m2 = area(a.polygon);
            const Vec2d c = centroid(a.polygon.outer);
            sea += m2;
            weighted = {weighted.x + c.x * m2, weighted.y + c.y * m2};
        }
    std::cout << "sea " << sea / 1e6 << " km^2, centre " << weighted.x / sea << ", " << weighted.y / sea << " m; warnings "
              << city.warnings.size() << "\n";
    EXPECT_GT(sea, 0.2e6) << "the bay";
    EXPECT_GT(weighted.x / sea, 0.0) << "east of the box's centre";
    EXPECT_GT(weighted.y / sea, 0.0) << "north of it";
}
