// Where street lamps stand: rows by road width, clear of buildings, carriageways and junctions,
// mapped lamps kept and turned to their road, deterministic; checked on hand-made roads and on the
// real extracts.
#include "model/polygon_ops.h"
#include "osm/osm_import.h"
#include "streets/lamp_placement.h"
#include "streets/road_elevation.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <filesystem>

using namespace urbis;

namespace {

Road straightRoad(Vec2d a, Vec2d b, float width, HighwayClass h = HighwayClass::Residential) {
    Road r;
    r.centerline = {a, b};
    r.width = width;
    r.highway = h;
    r.sidewalkLeftWidth = r.sidewalkRightWidth = 2.0f;
    return r;
}

double distanceToLine(Vec2d p, const std::vector<Vec2d>& line) {
    double best = 1e30;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2d a = line[i], b = line[i + 1];
        const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
    }
    return best;
}

std::vector<Lamp> placedOnly(const std::vector<Lamp>& lamps, size_t mapped) {
    return {lamps.begin() + std::ptrdiff_t(mapped), lamps.end()};
}

/// Nodes where three or more carriageway edges meet.
std::vector<Vec2d> junctionNodes(const std::vector<Road>& roads) {
    std::map<std::pair<double, double>, int> degree;
    for (const Road& r : roads) {
        if (r.highway == HighwayClass::Footway || r.highway == HighwayClass::Cycleway || r.highway == HighwayClass::Path ||
            r.highway == HighwayClass::Steps || !atSurface(r))
            continue;
        for (size_t i = 0; i < r.centerline.size(); ++i)
            degree[{r.centerline[i].x, r.centerline[i].y}] += i == 0 || i + 1 == r.centerline.size() ? 1 : 2;
    }
    std::vector<Vec2d> out;
    for (const auto& [p, d] : degree)
        if (d >= 3) out.push_back({p.first, p.second});
    return out;
}

bool isCarriageway(const Road& r) {
    return r.highway != HighwayClass::Footway && r.highway != HighwayClass::Cycleway && r.highway != HighwayClass::Path &&
           r.highway != HighwayClass::Steps && !r.tunnel && !r.underground && !r.covered && r.layer >= 0;
}

/// Every placed lamp is off every footprint and carriageway and away from junctions.
void expectClear(const CityModel& city, const std::vector<Road>& roads, const std::vector<Lamp>& placed) {
    const std::vector<Vec2d> junctions = junctionNodes(roads);
    std::vector<std::array<Vec2d, 2>> boxes;
    for (const Building& b : city.buildings) boxes.push_back(bounds(b.footprint.outer));
    for (const Lamp& l : placed) {
        const Vec2d p = l.position;
        for (size_t b = 0; b < boxes.size(); ++b)
            if (p.x >= boxes[b][0].x && p.x <= boxes[b][1].x && p.y >= boxes[b][0].y && p.y <= boxes[b][1].y) {
                ASSERT_FALSE(contains(city.buildings[b].footprint, p)) << p.x << ", " << p.y;
            }
        for (const Road& r : roads) {
            if (!isCarriageway(r)) continue;
            ASSERT_GT(distanceToLine(l.position, r.centerline), 0.5 * r.width + 0.1) << r.osmId;
        }
        for (Vec2d j : junctions) ASSERT_GE(std::hypot(l.position.x - j.x, l.position.y - j.y), 8.0);
    }
}

bool sameLamps(const std::vector<Lamp>& a, const std::vector<Lamp>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].position.x != b[i].position.x || a[i].position.y != b[i].position.y || a[i].direction != b[i].direction ||
            a[i].head != b[i].head || a[i].height != b[i].height)
            return false;
    return true;
}

} // namespace

TEST(LampPlacement, NarrowRoadHasOneRowOnTheSidewalkLeaningToTheRoad) {
    CityModel city;
    const std::vector<Road> roads = {straightRoad({0, 0}, {200, 0}, 6.0f)};
    const std::vector<Lamp> lamps = streetLamps(city, roads);
    ASSERT_EQ(lamps.size(), 5u);   // 19, 57, 95, 133, 171 m at 38 m spacing
    for (const Lamp& l : lamps) {
        EXPECT_NEAR(l.position.y, -3.5, 1e-9);   // right of the way: half the width + 0.5 m
        EXPECT_NEAR(l.direction, 0.0f, 1e-4f);   // leaning north, to the road
        EXPECT_EQ(l.osmId, 0);
    }
    EXPECT_NEAR(lamps[1].position.x - lamps[0].position.x, lampStyle(HighwayClass::Residential).spacing, 1e-9);
}

TEST(LampPlacement, SidewalkOnOneSideTakesTheRowAndBareEdgesGetLampsBesideThem) {
    CityModel city;
    Road left = straightRoad({0, 0}, {100, 0}, 6.0f);
    left.sidewalkRightWidth = 0;
    Road bare = straightRoad({0, 50}, {100, 50}, 6.0f);
    bare.sidewalkLeftWidth = bare.sidewalkRightWidth = 0;
    for (const Lamp& l : streetLamps(city, {left})) EXPECT_NEAR(l.position.y, 3.5, 1e-9);
    for (const Lamp& l : streetLamps(city, {bare})) EXPECT_NEAR(l.position.y, 46.5, 1e-9);
}

TEST(LampPlacement, WideRoadsHaveStaggeredRowsAndDualCarriagewaysAMedian) {
    CityModel city;
    const std::vector<Lamp> wide = streetLamps(city, {straightRoad({0, 0}, {300, 0}, 14.0f, HighwayClass::Primary)});
    int left = 0, right = 0;
    for (const Lamp& l : wide) {
        (l.position.y > 0 ? left : right)++;
        EXPECT_NEAR(std::fabs(l.position.y), 7.5, 1e-9);
        EXPECT_EQ(l.mount, LampMount::BentMast);
        EXPECT_NEAR(l.direction, l.position.y > 0 ? 180.0f : 0.0f, 1e-4f);
    }
    EXPECT_EQ(left, 9);
    EXPECT_EQ(right, 10);
    // Staggered: each left lamp halfway between two right ones.
    EXPECT_NEAR(std::fmod(wide.back().position.x - wide.front().position.x, 30.0), 15.0, 1e-9);

    // No median is drawn on a wide road, so its lamps stand beside it too, never on it.
    const std::vector<Lamp> widest = streetLamps(city, {straightRoad({0, 0}, {300, 0}, 24.0f, HighwayClass::Primary)});
    ASSERT_FALSE(widest.empty());
    for (const Lamp& l : widest) EXPECT_GT(std::fabs(l.position.y), 12.0);
}

TEST(LampPlacement, NoneNearJunctionsInsideBuildingsOrOnOtherRoads) {
    CityModel city;
    // A T junction at (100, 0), a crossing road at x = 50 that is a carriageway too, and a building
    // over the sidewalk from x = 120 to 180.
    std::vector<Road> roads = {straightRoad({0, 0}, {100, 0}, 6.0f), straightRoad({100, 0}, {300, 0}, 6.0f),
                               straightRoad({100, 0}, {100, 200}, 6.0f), straightRoad({57, -40}, {57, 40}, 8.0f)};
    Building b;
    b.footprint.outer = {{120, -10}, {180, -10}, {180, -3}, {120, -3}};
    city.buildings.push_back(b);
    const std::vector<Lamp> lamps = streetLamps(city, roads);
    EXPECT_GT(lamps.size(), 5u);
    expectClear(city, roads, lamps);
    for (const Lamp& l : lamps) {
        EXPECT_FALSE(l.position.x > 119.5 && l.position.x < 180.5 && l.position.y < -2.5) << l.position.x;
        if (std::fabs(l.position.y) < 5.0) {
            EXPECT_GT(std::fabs(l.position.x - 57.0), 4.2) << "on the crossing road";
        }
    }
}

TEST(LampPlacement, MappedLampsAreKeptTurnedToTheRoadAndStandForPlacedOnes) {
    CityModel city;
    Lamp mapped;
    mapped.osmId = 42;
    mapped.position = {57.0, 5.0};
    mapped.head = LampHead::Lantern;
    city.lamps.push_back(mapped);
    const std::vector<Lamp> lamps = streetLamps(city, {straightRoad({0, 0}, {200, 0}, 6.0f)});
    ASSERT_GE(lamps.size(), 1u);
    EXPECT_EQ(lamps[0].osmId, 42);
    EXPECT_EQ(lamps[0].head, LampHead::Lantern);
    EXPECT_NEAR(lamps[0].direction, 180.0f, 1e-4f);   // the road is south of it
    for (size_t i = 1; i < lamps.size(); ++i)
        EXPECT_GE(std::hypot(lamps[i].position.x - 57.0, lamps[i].position.y - 5.0), 19.0) << i;
    EXPECT_EQ(lamps.size(), 5u);   // the lamp at 57 m is mapped
}

TEST(LampPlacement, FootwaysTunnelsAndDegenerateRoadsGetNone) {
    CityModel city;
    Road footway = straightRoad({0, 0}, {200, 0}, 2.0f, HighwayClass::Footway);
    Road tunnel = straightRoad({0, 0}, {200, 0}, 6.0f);
    tunnel.tunnel = true;
    Road point = straightRoad({5, 5}, {5, 5}, 6.0f);
    Road huge = straightRoad({1e300, 0}, {INFINITY, 0}, 6.0f);
    EXPECT_TRUE(streetLamps(city, {footway, tunnel, point, huge}).empty());
}

namespace {

struct Extract {
    const char* name;
    std::string path;
    size_t leastPlaced;   ///< the village has 280 m of residential streets, the rest tracks and driveways
};

void checkExtract(const Extract& e) {
    if (!std::filesystem::exists(e.path)) GTEST_SKIP() << e.path << " not found (the shared data), skipping";
    const CityModel city = importOsm(e.path, ImportOptions{});
    std::vector<Road> roads = city.roads;
    // Sidewalks as tagged, else 2 m each side of streets that usually have them (the fitting's default).
    for (Road& r : roads) {
        const bool both = r.sidewalk == Sidewalk::Both || (r.sidewalk == Sidewalk::Unknown && r.highway <= HighwayClass::Residential);
        if (r.sidewalkLeftWidth == 0 && (both || r.sidewalk == Sidewalk::Left)) r.sidewalkLeftWidth = 2.0f;
        if (r.sidewalkRightWidth == 0 && (both || r.sidewalk == Sidewalk::Right)) r.sidewalkRightWidth = 2.0f;
    }
    const std::vector<Lamp> lamps = streetLamps(city, roads);
    ASSERT_GE(lamps.size(), city.lamps.size());
    for (size_t i = 0; i < city.lamps.size(); ++i) EXPECT_EQ(lamps[i].osmId, city.lamps[i].osmId);
    const std::vector<Lamp> placed = placedOnly(lamps, city.lamps.size());
    EXPECT_GE(placed.size(), e.leastPlaced) << e.name;
    expectClear(city, roads, placed);
    EXPECT_TRUE(sameLamps(lamps, streetLamps(city, roads))) << "deterministic";
    std::printf("%s: %zu mapped, %zu placed lamps along %zu roads\n", e.name, city.lamps.size(), placed.size(), roads.size());
}

} // namespace

TEST(LampPlacement, RealVillageLampsAreClear) {
    checkExtract({"village", URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm", 6});
}
TEST(LampPlacement, RealWestOaklandLampsAreClear) { checkExtract({"West Oakland", URBIS_OSMNX_DATA "/West-Oakland.osm.bz2", 40}); }
TEST(LampPlacement, RealSanFranciscoLampsAreClear) {
    checkExtract({"San Francisco", URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf", 3000});
}
