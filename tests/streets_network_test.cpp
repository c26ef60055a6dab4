// The road network: fitting (surface-only roads, sidewalks from tags and class, mapped sidewalks not
// doubled, corridors squeezed between buildings, centerlines cut where they run through one), the
// RoadSegment records of a straight two-lane road (distance, width, lanes, markings, stop lines at a
// junction, a zebra at a crossing), no road polygon over a building on the real extracts, determinism
// and the time it takes on SF.
#include "streets_network_support.h"

#include "layout/city_layout.h"
#include "osm/osm_import.h"
#include "scene/road_segment.h"

#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <map>

using namespace urbis;
using namespace urbis::test;

namespace {

std::vector<Road> fit(const CityModel& city, std::map<std::string, uint64_t>& dropped) { return fitRoads(city, dropped); }

std::vector<Road> fit(const CityModel& city) {
    std::map<std::string, uint64_t> dropped;
    return fitRoads(city, dropped);
}

} // namespace

TEST(StreetsNetworkFitting, DropsRoadsNotAtTheSurface) {
    CityModel city;
    for (int i = 0; i < 5; ++i) city.roads.push_back(street({{0, double(10 * i)}, {50, double(10 * i)}}));
    city.roads[0].tunnel = true;
    city.roads[1].covered = true;
    city.roads[2].underground = true;
    city.roads[3].layer = -1;
    city.roads[4].layer = -1;
    city.roads[4].bridge = true;   // a bridge below a higher one: still at the surface
    std::map<std::string, uint64_t> dropped;
    const std::vector<Road> fitted = fit(city, dropped);
    ASSERT_EQ(fitted.size(), 1u);
    EXPECT_TRUE(fitted[0].bridge);
    EXPECT_EQ(dropped["road_not_at_surface"], 4u);
}

TEST(StreetsNetworkFitting, SidewalksFromTagsClassAndMappedSidewalks) {
    CityModel city;
    city.buildings.push_back(box(0, 30, 100, 40));   // in town
    city.roads.push_back(street({{0, 0}, {100, 0}}, 6.0f, Sidewalk::Unknown));     // residential: both
    city.roads.push_back(street({{0, 10}, {100, 10}}, 4.0f, Sidewalk::Unknown));   // service: none
    city.roads[1].highway = HighwayClass::Service;
    city.roads.push_back(street({{0, 20}, {100, 20}}, 6.0f, Sidewalk::Separate));
    city.roads.push_back(street({{0, -20}, {100, -20}}, 6.0f, Sidewalk::Left));
    city.roads[3].sidewalkLeftWidth = 1.5f;
    city.roads.push_back(street({{0, -500}, {100, -500}}, 6.0f, Sidewalk::Unknown));  // out of town: none
    const std::vector<Road> fitted = fit(city);
    ASSERT_EQ(fitted.size(), 5u);
    EXPECT_EQ(fitted[0].sidewalk, Sidewalk::Both);
    EXPECT_FLOAT_EQ(fitted[0].sidewalkLeftWidth, defaultSidewalkWidth(HighwayClass::Residential));
    EXPECT_FLOAT_EQ(fitted[0].sidewalkRightWidth, defaultSidewalkWidth(HighwayClass::Residential));
    EXPECT_EQ(fitted[1].sidewalk, Sidewalk::None);
    EXPECT_EQ(fitted[2].sidewalk, Sidewalk::None);
    EXPECT_EQ(fitted[3].sidewalk, Sidewalk::Left);
    EXPECT_FLOAT_EQ(fitted[3].sidewalkLeftWidth, 1.5f);
    EXPECT_FLOAT_EQ(fitted[3].sidewalkRightWidth, 0.0f);
    EXPECT_EQ(fitted[4].sidewalk, Sidewalk::None);

    // A mapped footway=sidewalk 6 m left of the road: no second sidewalk on that side.
    Road footway = street({{0, 6}, {100, 6}}, 2.0f, Sidewalk::Unknown);
    footway.highway = HighwayClass::Footway;
    footway.footway = FootwayKind::Sidewalk;
    city.roads = {city.roads[0], footway};
    const std::vector<Road> mapped = fit(city);
    ASSERT_EQ(mapped.size(), 2u);
    EXPECT_EQ(mapped[0].sidewalk, Sidewalk::Right);
    EXPECT_FLOAT_EQ(mapped[0].sidewalkLeftWidth, 0.0f);
    EXPECT_EQ(mapped[1].sidewalk, Sidewalk::None);   // the footway itself is a path
}

TEST(StreetsNetworkFitting, ShrinksARoadSqueezedBetweenBuildings) {
    CityModel city;
    city.roads.push_back(street({{0, 0}, {60, 0}}));
    city.buildings = {box(20, 4, 40, 20), box(20, -20, 40, -5)};
    // 4 m to the left, 5 m to the right (less the 5 cm kept clear): sidewalks shrink, the carriageway keeps 6 m.
    std::vector<Road> fitted = fit(city);
    ASSERT_EQ(fitted.size(), 1u);
    EXPECT_NEAR(fitted[0].width, 6.0f, 1e-5f);
    EXPECT_NEAR(fitted[0].sidewalkLeftWidth, 0.95f, 1e-5f);
    EXPECT_NEAR(fitted[0].sidewalkRightWidth, 1.95f, 1e-5f);
    EXPECT_EQ(fitted[0].sidewalk, Sidewalk::Both);

    // 2 m each side: no sidewalks, and the carriageway as wide as the street between the buildings.
    city.buildings = {box(20, 2, 40, 20), box(20, -20, 40, -2)};
    fitted = fit(city);
    ASSERT_EQ(fitted.size(), 1u);
    EXPECT_NEAR(fitted[0].width, 3.9f, 1e-5f);
    EXPECT_EQ(fitted[0].sidewalk, Sidewalk::None);
    EXPECT_EQ(fitted[0].sidewalkLeftWidth + fitted[0].sidewalkRightWidth, 0.0f);
}

TEST(StreetsNetworkFitting, CutsACenterlineThroughABuilding) {
    CityModel city;
    city.roads.push_back(street({{0, 0}, {60, 0}}));
    city.buildings = {box(25, -10, 35, 10)};
    std::map<std::string, uint64_t> dropped;
    const std::vector<Road> fitted = fit(city, dropped);
    ASSERT_EQ(fitted.size(), 2u);
    EXPECT_EQ(dropped["road_piece_in_building"], 1u);
    EXPECT_LE(fitted[0].centerline.back().x, 25.0);
    EXPECT_GE(fitted[0].centerline.back().x, 23.0);
    EXPECT_GE(fitted[1].centerline.front().x, 35.0);
    EXPECT_LE(fitted[1].centerline.front().x, 37.0);
}

TEST(StreetsNetworkSegments, StraightTwoLaneRoad) {
    // A T: west and east arms of one street meet a north one at (0, 0); a zebra at (25, 0).
    CityModel city;
    city.roads.push_back(street({{-50, 0}, {0, 0}}));
    city.roads.push_back(street({{0, 0}, {25, 0}, {50, 0}}));
    city.roads.push_back(street({{0, 0}, {0, 50}}));
    city.crossings.push_back({1, {25, 0}, CrossingKind::Zebra});
    StreetOptions options;
    options.firstMaterial = 10;
    options.firstObject = 100;
    const std::vector<Road> fitted = fit(city);
    ASSERT_EQ(fitted.size(), 3u);
    StreetMesh mesh;
    meshStreetNetwork(city, fitted, {}, options, mesh);
    ASSERT_EQ(mesh.roadSegments.size(), 4u);   // one per centerline segment
    const uint32_t lines = kMarkCentreLine | kMarkCentreDashed;
    const RoadSegment& west = mesh.roadSegments[0];
    EXPECT_EQ(west.markings, lines | kMarkStopAtEnd);
    EXPECT_FLOAT_EQ(west.distance, 0.0f);
    EXPECT_NEAR(west.direction.x, 1.0f, 1e-6f);
    EXPECT_NEAR(west.direction.y, 0.0f, 1e-6f);
    EXPECT_LT(west.length, 50.0f - 2.9f);   // trimmed back at least half the north street's width
    const RoadSegment& east0 = mesh.roadSegments[1];
    const RoadSegment& east1 = mesh.roadSegments[2];
    EXPECT_EQ(east0.markings, lines | kMarkStopAtStart | kMarkZebraAtEnd);
    EXPECT_EQ(east1.markings, lines | kMarkZebraAtStart);
    EXPECT_GT(east0.distance, 2.9f);        // its start was trimmed: distance runs from the way's node
    EXPECT_FLOAT_EQ(east0.distance + east0.length, 25.0f);
    EXPECT_FLOAT_EQ(east1.distance, 25.0f);
    EXPECT_FLOAT_EQ(east1.length, 25.0f);
    EXPECT_FLOAT_EQ(east1.start.x, 25.0f);
    EXPECT_FLOAT_EQ(east1.start.y, 0.0f);
    for (const RoadSegment& s : mesh.roadSegments) {
        EXPECT_FLOAT_EQ(s.halfWidth, 3.0f);
        EXPECT_EQ(s.lanesForward, 1);
        EXPECT_EQ(s.lanesBackward, 1);
        EXPECT_FLOAT_EQ(s.centreOffset, 0.0f);
        EXPECT_EQ(s.paint, 10u + uint32_t(StreetMaterial::PaintWhite));
    }
    EXPECT_EQ(east1.object, 101u);
    const RoadSegment& north = mesh.roadSegments[3];
    EXPECT_NEAR(north.direction.y, -1.0f, 1e-6f);   // north is world -z
    EXPECT_EQ(north.markings, lines | kMarkStopAtStart);
    EXPECT_EQ(mesh.counts["crossings"], 1u);
    EXPECT_EQ(mesh.counts["junctions"], 1u);
    EXPECT_EQ(mesh.counts["roads"], 3u);
    EXPECT_EQ(mesh.objects, 3u);
    // A Road triangle's object is its segment; every segment has triangles.
    std::vector<int> trianglesOf(mesh.roadSegments.size(), 0);
    for (size_t i = 0; i < mesh.mesh.size(); ++i)
        if (mesh.mesh.info[i].part == uint32_t(SurfacePart::Road)) ++trianglesOf.at(mesh.mesh.info[i].object);
    for (int n : trianglesOf) EXPECT_EQ(n, 2);

    // A oneway of three lanes: all forward, the line between directions on its left edge.
    city.roads[1].oneway = true;
    city.roads[1].lanes = 3;
    StreetMesh oneway;
    meshStreetNetwork(city, fit(city), {}, options, oneway);
    EXPECT_EQ(oneway.roadSegments[1].lanesForward, 3);
    EXPECT_EQ(oneway.roadSegments[1].lanesBackward, 0);
    EXPECT_FLOAT_EQ(oneway.roadSegments[1].centreOffset, oneway.roadSegments[1].halfWidth);
    EXPECT_EQ(oneway.roadSegments[1].markings & kMarkLaneDividers, kMarkLaneDividers);
}

namespace {

struct Extract {
    const char* name;
    std::string path;   ///< empty: the generated city
    bool required;
    double overShare;   ///< share of roads tolerated over a building by more than kOverlapTolerance
};

void PrintTo(const Extract& e, std::ostream* os) { *os << e.name; }

class NetworkExtract : public testing::TestWithParam<Extract> {};

} // namespace

/// Tolerated plan overlap of one road's surfaces (carriageway, junctions it names, sidewalks) with
/// building footprints (those starting at the ground, as fitting sees them): 1 cm^2. None may pass it
/// on the osmnx extracts; on SF 117 of 12,755 do (0.9 %: sidewalk corners and mitres at buildings'
/// corners, where a trim was capped), held at 1.5 %; in the generated city (3,000 buildings) 15 of 671
/// (2.2 %, the worst by 56 m^2), held at 3 %.
constexpr double kOverlapTolerance = 1e-4;

TEST_P(NetworkExtract, RoadsDoNotOverlapBuildings) {
    const Extract& e = GetParam();
    if (!e.path.empty() && !std::filesystem::exists(e.path)) {
        ASSERT_FALSE(e.required) << e.path << " is missing";
        GTEST_SKIP() << e.path << " not found, skipping";
    }
    LayoutParams generated;
    generated.buildings = 3000;   // big enough for the river, its bridges, parks and arterial junctions
    const CityModel city = e.path.empty() ? generateCity(generated) : importOsm(e.path, {});
    // Wall time depends on what else the machine runs: the processor time is the figure to compare.
    const auto begin = std::chrono::steady_clock::now();
    const std::clock_t cpuBegin = std::clock();
    StreetMesh mesh;
    const std::vector<Road> fitted = fitRoads(city, mesh.dropped);
    meshStreetNetwork(city, fitted, {}, StreetOptions{}, mesh);
    const double cpu = double(std::clock() - cpuBegin) / CLOCKS_PER_SEC;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::cout << e.name << ": " << city.roads.size() << " ways -> " << fitted.size() << " roads, "
              << mesh.mesh.size() << " triangles, " << mesh.roadSegments.size() << " segments, "
              << mesh.counts["junctions"] << " junctions in " << cpu << " s of processor time (" << seconds
              << " s wall)\n";
    for (const auto& [reason, n] : mesh.dropped) std::cout << "  dropped " << reason << ": " << n << "\n";
    ASSERT_GT(mesh.counts["roads"], 0u);

    CellGrid grid(50.0);
    for (uint32_t i = 0; i < city.buildings.size(); ++i) {
        const Building& b = city.buildings[i];
        if (b.minHeight > 2.5f || b.footprint.outer.size() < 3) continue;
        Vec2d lo{1e30, 1e30}, hi{-1e30, -1e30};
        for (const Vec2d& p : b.footprint.outer) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
        grid.insert(i, {lo, hi});
    }
    std::map<uint32_t, double> overlapOf;   // road object -> m^2
    for (size_t t = 0; t < mesh.mesh.size(); ++t) {
        const Triangle& tri = mesh.mesh.triangles[t];
        if (tri.p0.y != tri.p1.y || tri.p0.y != tri.p2.y) continue;   // the tops only
        const TriangleInfo info = mesh.mesh.info[t];
        const uint32_t road = info.part == uint32_t(SurfacePart::Road) ? mesh.roadSegments[info.object].object
                                                                        : uint32_t(info.object);
        const Vec2d a{tri.p0.x, -tri.p0.z}, b{tri.p1.x, -tri.p1.z}, c{tri.p2.x, -tri.p2.z};
        std::vector<uint32_t> near;
        grid.query({Vec2d{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})},
                    Vec2d{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})}},
                   [&](uint32_t i) { near.push_back(i); });
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        for (uint32_t i : near) {
            const Polygon& fp = city.buildings[i].footprint;
            double area = areaInTriangle(fp.outer, a, b, c);
            for (const Ring& hole : fp.holes) area -= areaInTriangle(hole, a, b, c);
            if (area > 0) overlapOf[road] += area;
        }
    }
    size_t over = 0;
    double worst = 0;
    for (const auto& [road, area] : overlapOf) {
        over += area > kOverlapTolerance ? 1 : 0;
        worst = std::max(worst, area);
    }
    std::cout << "  roads over a building: " << over << " of " << fitted.size() << ", worst " << worst << " m^2\n";
    EXPECT_LE(double(over), e.overShare * double(fitted.size())) << "worst overlap " << worst << " m^2";
}

INSTANTIATE_TEST_SUITE_P(
    Streets, NetworkExtract,
    testing::Values(Extract{"Generated", "", true, 0.03},
                    Extract{"Village", std::string(URBIS_OSMNX_DATA) + "/planet_10.068,48.135_10.071,48.137.osm", true, 0.0},
                    Extract{"WestOakland", std::string(URBIS_OSMNX_DATA) + "/West-Oakland.osm.bz2", true, 0.0},
                    Extract{"SanFrancisco", std::string(URBIS_SHARED_DATA) + "/sf_downtown_2023.osm.pbf", false, 0.015}));

TEST(StreetsNetwork, Deterministic) {
    const CityModel city =
        importOsm(std::string(URBIS_OSMNX_DATA) + "/West-Oakland.osm.bz2", {});
    const auto mesh = [&]() {
        StreetMesh m;
        meshStreetNetwork(city, fitRoads(city, m.dropped), {}, StreetOptions{}, m);
        return m;
    };
    const StreetMesh a = mesh(), b = mesh();
    ASSERT_EQ(a.mesh.size(), b.mesh.size());
    ASSERT_GT(a.mesh.size(), 0u);
    EXPECT_EQ(std::memcmp(a.mesh.triangles.data(), b.mesh.triangles.data(), a.mesh.size() * sizeof(Triangle)), 0);
    EXPECT_EQ(std::memcmp(a.mesh.info.data(), b.mesh.info.data(), a.mesh.size() * sizeof(TriangleInfo)), 0);
    ASSERT_EQ(a.roadSegments.size(), b.roadSegments.size());
    EXPECT_EQ(std::memcmp(a.roadSegments.data(), b.roadSegments.data(), a.roadSegments.size() * sizeof(RoadSegment)), 0);
    EXPECT_EQ(a.counts, b.counts);
}
