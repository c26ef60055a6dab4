// Ground cover: triangles that cover each polygon exactly (holes, concave and self-touching rings),
// planes that keep overlapping areas apart (traced from above: the higher priority, or the smaller
// of one priority, is the one seen, and the other lies strictly below), degenerate areas counted,
// coastline-sized rings without interior points, and every area of the osmnx extracts accounted for.
#include "geometry/scene_intersect.h"
#include "model/polygon_ops.h"
#include "osm/osm_import.h"
#include "scene/scene.h"
#include "streets/ground_cover.h"
#include "streets/ground_cover_levels.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <stdexcept>

using namespace urbis;

namespace {

Ring square(double x0, double y0, double side) {
    return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Area areaOf(AreaKind kind, Polygon polygon, int64_t id = 1) {
    Area a;
    a.osmId = id;
    a.kind = kind;
    a.polygon = std::move(polygon);
    return a;
}

StreetMesh meshAreas(std::vector<Area> areas, StreetOptions options = {}) {
    CityModel city;
    city.areas = std::move(areas);
    StreetMesh out;
    meshGroundCover(city, options, out);
    return out;
}

/// Plan area (x, -z) of the mesh's triangles.
double meshArea(const TriangleMesh& mesh) {
    double sum = 0;
    for (const Triangle& t : mesh.triangles) {
        const double ax = t.p1.x - t.p0.x, az = t.p1.z - t.p0.z, bx = t.p2.x - t.p0.x, bz = t.p2.z - t.p0.z;
        sum += 0.5 * std::fabs(ax * bz - az * bx);
    }
    return sum;
}

uint64_t droppedCount(const StreetMesh& out, const std::string& reason) {
    const auto it = out.dropped.find(reason);
    return it == out.dropped.end() ? 0 : it->second;
}

/// Each area drawn over a ground, as a scene with streetMaterials() from material 0.
Scene sceneOf(const StreetMesh& out) {
    return Scene::build({.mesh = out.mesh, .materials = streetMaterials(),
                         .grounds = {GroundRecord::around(0, 0, 0, 0)}});
}

/// Every surface a vertical ray down through local (x, y) meets, top first.
std::vector<SurfaceHit> hitsDown(const SceneView& view, double x, double y) {
    std::vector<SurfaceHit> hits;
    Ray ray{{float(x), 10.0f, float(-y)}, {0, -1, 0}};
    for (SurfaceHit h = intersectScene(view, ray); h.valid() && hits.size() < 32; h = intersectScene(view, ray)) {
        hits.push_back(h);
        ray.origin.y = h.position.y - 1e-5f;   // on from just under the hit: the planes lie mm apart
    }
    return hits;
}

uint32_t materialIndex(StreetMaterial m) { return uint32_t(m); }

} // namespace

TEST(StreetsGroundCover, TrianglesCoverASquareWithAHole) {
    Polygon p{square(0, 0, 10), {square(3, 3, 4)}};
    orient(p);
    const StreetMesh out = meshAreas({areaOf(AreaKind::Park, p)});
    EXPECT_NEAR(meshArea(out.mesh), area(p), 1e-6 * area(p));
    EXPECT_EQ(area(p), 84.0);
    EXPECT_EQ(out.counts.at("ground_cover"), 1u);
    EXPECT_EQ(out.trianglesByKind.at("ground_cover"), out.mesh.size());
    // Constrained Delaunay of the rings' 8 points and nothing inside: 8 triangles.
    EXPECT_EQ(out.mesh.size(), 8u);
}

TEST(StreetsGroundCover, TrianglesCoverAnLShape) {
    const Polygon p{{{0, 0}, {20, 0}, {20, 5}, {5, 5}, {5, 30}, {0, 30}}, {}};
    const StreetMesh out = meshAreas({areaOf(AreaKind::Grass, p)});
    EXPECT_NEAR(meshArea(out.mesh), area(p), 1e-6 * area(p));
    EXPECT_EQ(out.mesh.size(), 4u);
}

TEST(StreetsGroundCover, TrianglesCoverASelfTouchingRing) {
    // Two squares joined at the point (10, 10) by one ring that passes through it twice: GEOS calls
    // it invalid, and made valid it must keep both halves.
    const Polygon p{{{0, 0}, {10, 0}, {10, 10}, {20, 10}, {20, 20}, {10, 20}, {10, 10}, {0, 10}}, {}};
    ASSERT_EQ(area(p), 200.0);
    const StreetMesh out = meshAreas({areaOf(AreaKind::Sand, p)});
    EXPECT_NEAR(meshArea(out.mesh), 200.0, 200.0 * 1e-6);
    EXPECT_EQ(out.counts.at("ground_cover"), 1u);
}

TEST(StreetsGroundCover, DegenerateAreasAreDroppedAndCounted) {
    std::vector<Area> areas = {
        areaOf(AreaKind::Park, {{{0, 0}, {1, 1}}, {}}),                           // two points
        areaOf(AreaKind::Park, {{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}}),           // no area
        areaOf(AreaKind::Park, {{{0, 0}, {NAN, 1}, {2, 0}}, {}}),                 // not finite
        areaOf(AreaKind::Park, {{{0, 0}, {1e12, 0}, {1e12, 1e12}}, {}}),          // far beyond any extract
        areaOf(AreaKind::Park, {{{0, 0}, {0, 0}, {0, 0}}, {}}),                   // one point thrice
        areaOf(AreaKind::Water, {square(0, 0, 10), {{{1, 1}, {2, 2}}}}),          // kept, its hole skipped
    };
    const StreetMesh out = meshAreas(areas);
    EXPECT_EQ(droppedCount(out, "area_degenerate"), 5u);
    EXPECT_EQ(droppedCount(out, "area_hole_degenerate"), 1u);
    EXPECT_EQ(out.counts.at("water"), 1u);
    EXPECT_EQ(out.counts.at("ground_cover"), 0u);
    for (const Triangle& t : out.mesh.triangles)
        for (const Vec3f& p : {t.p0, t.p1, t.p2}) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.z));
}

TEST(StreetsGroundCover, StylesFollowKindAndSurface) {
    Area pedestrian = areaOf(AreaKind::Pedestrian, {});
    EXPECT_EQ(coverStyleOf(pedestrian).material, StreetMaterial::PavingStones);
    EXPECT_EQ(coverStyleOf(pedestrian).part, SurfacePart::Sidewalk);
    pedestrian.surface = RoadSurface::Sett;
    EXPECT_EQ(coverStyleOf(pedestrian).material, StreetMaterial::Sett);
    Area parking = areaOf(AreaKind::Parking, {});
    EXPECT_EQ(coverStyleOf(parking).material, StreetMaterial::Parking);
    parking.surface = RoadSurface::Gravel;
    EXPECT_EQ(coverStyleOf(parking).material, StreetMaterial::Gravel);
    EXPECT_EQ(coverStyleOf(areaOf(AreaKind::Water, {})).part, SurfacePart::Water);
    EXPECT_EQ(coverStyleOf(areaOf(AreaKind::Forest, {})).part, SurfacePart::GroundCover);
    EXPECT_LT(coverStyleOf(areaOf(AreaKind::Residential, {})).priority, coverStyleOf(areaOf(AreaKind::Park, {})).priority);
    EXPECT_LT(coverStyleOf(areaOf(AreaKind::Park, {})).priority, coverStyleOf(areaOf(AreaKind::Pitch, {})).priority);
    EXPECT_LT(coverStyleOf(areaOf(AreaKind::Pitch, {})).priority, coverStyleOf(areaOf(AreaKind::Parking, {})).priority);
}

TEST(StreetsGroundCover, ObjectIdsFollowThoseAlreadyTaken) {
    CityModel city;
    city.areas = {areaOf(AreaKind::Park, {square(0, 0, 5), {}}), areaOf(AreaKind::Park, {{{0, 0}}, {}}),
                  areaOf(AreaKind::Water, {square(10, 0, 5), {}})};
    StreetOptions options;
    options.firstObject = 100;
    StreetMesh out;
    out.objects = 7;   // another part took 100..106
    meshGroundCover(city, options, out);
    EXPECT_EQ(out.objects, 9u);
    std::set<uint32_t> ids;
    for (const TriangleInfo& info : out.mesh.info) ids.insert(info.object);
    EXPECT_EQ(ids, (std::set<uint32_t>{107, 108}));
}

// A park over residential landuse: from above the park is what a ray sees, and the landuse under it
// lies strictly lower; where only the landuse is, the ray sees it.
TEST(StreetsGroundCover, HigherPriorityLiesAboveWhereAreasOverlap) {
    const StreetMesh out = meshAreas({areaOf(AreaKind::Park, {square(20, 20, 30), {}}, 1),
                                      areaOf(AreaKind::Residential, {square(0, 0, 100), {}}, 2)});
    const Scene scene = sceneOf(out);
    const SceneView view = scene.view();
    for (double x = 21; x < 50; x += 4.7)
        for (double y = 21; y < 50; y += 3.9) {
            const std::vector<SurfaceHit> hits = hitsDown(view, x, y);
            ASSERT_EQ(hits.size(), 3u) << x << ", " << y;   // park, landuse, ground
            EXPECT_EQ(hits[0].material, materialIndex(StreetMaterial::Park));
            EXPECT_EQ(hits[1].material, materialIndex(StreetMaterial::ResidentialGround));
            EXPECT_GT(hits[0].position.y, hits[1].position.y + 0.5f * kCoverStep);
            EXPECT_GE(hits[1].position.y, kGroundCoverLevel - 1e-6f);
        }
    const std::vector<SurfaceHit> outside = hitsDown(view, 80, 80);
    ASSERT_EQ(outside.size(), 2u);
    EXPECT_EQ(outside[0].material, materialIndex(StreetMaterial::ResidentialGround));
}

// Nested parks (one priority): the smaller lies higher, whatever the areas' order; a pitch in them
// lies higher still; a paved square and water over them lie on their own bands, water over a bed
// that lies above every cover it overlaps.
TEST(StreetsGroundCover, EveryPileHasDistinctPlanesTopmostTheOneOfHighestPriority) {
    for (int flip = 0; flip < 2; ++flip) {
        std::vector<Area> areas = {areaOf(AreaKind::Park, {square(0, 0, 100), {}}, 1),
                                   areaOf(AreaKind::Park, {square(10, 10, 60), {}}, 2),
                                   areaOf(AreaKind::Pitch, {square(20, 20, 10), {}}, 3),
                                   areaOf(AreaKind::Pedestrian, {square(40, 20, 10), {}}, 4),
                                   areaOf(AreaKind::Water, {square(20, 40, 10), {}}, 5)};
        if (flip) std::reverse(areas.begin(), areas.end());
        const Scene scene = sceneOf(meshAreas(areas));
        const SceneView view = scene.view();
        auto expectPile = [&](double x, double y, std::vector<StreetMaterial> topFirst) {
            const std::vector<SurfaceHit> hits = hitsDown(view, x, y);
            ASSERT_EQ(hits.size(), topFirst.size() + 1) << x << ", " << y;
            for (size_t i = 0; i < topFirst.size(); ++i) {
                EXPECT_EQ(hits[i].material, materialIndex(topFirst[i])) << x << ", " << y << " #" << i;
                EXPECT_GT(hits[i].position.y, hits[i + 1].position.y + 0.5f * kCoverStep);
            }
        };
        using M = StreetMaterial;
        expectPile(5, 5, {M::Park});
        expectPile(15, 15, {M::Park, M::Park});
        expectPile(25, 25, {M::Pitch, M::Park, M::Park});
        expectPile(45, 25, {M::PavingStones, M::Park, M::Park});
        // The water cuts the parks away under it; its bed lies below the ground (docs/water.md).
        const std::vector<SurfaceHit> water = hitsDown(view, 25, 45);
        ASSERT_EQ(water.size(), 3u) << "surface, the ground, the bed";
        EXPECT_EQ(water[0].material, materialIndex(M::Water));
        EXPECT_NEAR(water[0].position.y, kWaterLevel, 1e-6f);
        EXPECT_EQ(water[2].material, materialIndex(M::WaterBed));
        EXPECT_LT(water[2].position.y, 0.0f);
        EXPECT_EQ(water[0].part, SurfacePart::Water);
        EXPECT_EQ(water[2].part, SurfacePart::Water);
        EXPECT_EQ(hitsDown(view, 45, 25)[0].part, SurfacePart::Sidewalk);
        EXPECT_NEAR(hitsDown(view, 45, 25)[0].position.y, kPavedAreaLevel, 1e-6f);
    }
}

// Areas that only share an edge need no planes apart, so a city's landuse mosaic stays one plane.
TEST(StreetsGroundCover, AreasThatOnlyTouchShareAPlane) {
    const StreetMesh out = meshAreas({areaOf(AreaKind::Residential, {square(0, 0, 10), {}}, 1),
                                      areaOf(AreaKind::Commercial, {square(10, 0, 10), {}}, 2)});
    for (const Triangle& t : out.mesh.triangles) EXPECT_EQ(t.p0.y, kGroundCoverLevel);
}

// Water on water (a river inside a lake): one plane, the larger cut where the smaller lies, so no ray
// passes two water surfaces.
TEST(StreetsGroundCover, WaterNeverLiesOnWater) {
    const Polygon lake{square(0, 0, 100), {}}, river{square(40, -10, 20), {}};
    const StreetMesh out = meshAreas({areaOf(AreaKind::Water, lake, 1), areaOf(AreaKind::Water, river, 2),
                                      areaOf(AreaKind::Water, {square(45, 45, 5), {}}, 3)});
    EXPECT_EQ(out.counts.at("water"), 3u);
    const Scene scene = sceneOf(out);
    for (const auto& [x, y] : {std::pair{50.0, 5.0}, {50.0, -5.0}, {10.0, 10.0}, {47.0, 47.0}}) {
        const std::vector<SurfaceHit> hits = hitsDown(scene.view(), x, y);
        ASSERT_EQ(hits.size(), 3u) << x << ", " << y;   // surface, ground, bed below it
        EXPECT_EQ(hits[0].material, materialIndex(StreetMaterial::Water));
        EXPECT_EQ(hits[2].material, materialIndex(StreetMaterial::WaterBed));
    }
    // Surfaces and beds: the union of the lake and the river's part outside it, twice.
    EXPECT_NEAR(meshArea(out.mesh), 2 * (100.0 * 100.0 + 20.0 * 10.0), 1e-3);
}

TEST(StreetsGroundCover, APileDeeperThanTheBandIsCutAtItsTop) {
    const int planes = planesBetween(kGroundCoverLevel, kWaterLevel, kCoverStep);
    EXPECT_EQ(planes, 15);
    EXPECT_LT(kGroundCoverLevel + float(planes - 1) * kCoverStep, kWaterLevel);
    std::vector<Area> areas;
    for (int i = 0; i < planes + 3; ++i) areas.push_back(areaOf(AreaKind::Park, {square(i, i, 100 - 2 * i), {}}, i + 1));
    const StreetMesh out = meshAreas(areas);
    EXPECT_EQ(droppedCount(out, "area_too_deep"), 3u);
    EXPECT_EQ(out.counts.at("ground_cover"), uint64_t(planes));
    std::set<float> levels;
    for (const Triangle& t : out.mesh.triangles) levels.insert(t.p0.y);
    EXPECT_EQ(levels.size(), size_t(planes));
    EXPECT_LT(*levels.rbegin(), kWaterLevel);
}

TEST(StreetsGroundCover, StackPlanesPilesOnlyWhatOverlaps) {
    // 0 under 1 under 2; 3 overlaps only 0; 4 overlaps nothing.
    const std::set<std::pair<size_t, size_t>> overlapping = {{1, 0}, {2, 1}, {2, 0}, {3, 0}};
    const std::vector<PlaneBox> sameBox(5, PlaneBox{Vec2d{0, 0}, Vec2d{1, 1}});
    const std::vector<int> planes =
        stackPlanes(sameBox, 3, [&](size_t i, size_t j) { return overlapping.count({i, j}) > 0; });
    EXPECT_EQ(planes, (std::vector<int>{0, 1, 2, 1, 0}));
    EXPECT_EQ(stackPlanes({sameBox.begin(), sameBox.begin() + 3}, 2, [](size_t, size_t) { return true; }),
              (std::vector<int>{0, 1, -1}));
    // Boxes apart (or only touching) are never asked.
    const std::vector<PlaneBox> apart = {{Vec2d{0, 0}, Vec2d{1, 1}}, {Vec2d{1, 0}, Vec2d{2, 1}}, {Vec2d{5, 5}, Vec2d{6, 6}}};
    const auto never = [](size_t, size_t) -> bool { throw std::logic_error("asked"); };
    EXPECT_EQ(stackPlanes(apart, 3, never), (std::vector<int>{0, 0, 0}));
}

// A coastline-sized ring of 40,000 points: triangulated in pieces of a few hundred points (GEOS's
// triangulation grows faster than the square of the points), its surface about one triangle per
// point, surface and bed covering its area exactly.
TEST(StreetsGroundCover, ACoastlineSizedRingKeepsItsTriangleCountSane) {
    Ring coast;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n, r = 3000 + 40 * std::sin(37 * a) + 15 * std::sin(211 * a);
        coast.push_back({r * std::cos(a), r * std::sin(a)});
    }
    const Polygon p{coast, {}};
    const auto start = std::chrono::steady_clock::now();
    const StreetMesh out = meshAreas({areaOf(AreaKind::Water, p)});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const size_t triangles = size_t(std::count_if(out.mesh.triangles.begin(), out.mesh.triangles.end(),
                                                  [](const Triangle& t) { return t.p0.y == kWaterLevel; }));
    EXPECT_GE(triangles, size_t(n - 2));
    EXPECT_LT(triangles, size_t(1.1 * n));
    EXPECT_NEAR(meshArea(out.mesh), 2 * area(p), 2e-6 * area(p));
    EXPECT_LT(seconds, 30.0) << "a whole-ring triangulation took minutes";
    std::cout << "coastline of " << n << " points: " << triangles << " triangles in " << seconds << " s\n";
}

namespace {

struct Extract {
    const char* name;
    std::string path;
    bool required;   ///< always present (Debian's osmnx test data) or else skipped
};

const std::string kOsmnx = URBIS_OSMNX_DATA, kShared = URBIS_SHARED_DATA;

// The village's four landuse polygons reach beyond the extract and never close, so it has no areas:
// it checks that none are invented. The shared extracts have hundreds.
const Extract kExtracts[] = {
    {"Village", kOsmnx + "/planet_10.068,48.135_10.071,48.137.osm", true},
    {"WestOakland", kOsmnx + "/West-Oakland.osm.bz2", true},
    {"SanFrancisco", kShared + "/sf_downtown_2023.osm.pbf", false},
    {"London", kShared + "/london_city_2020.osm.pbf", false},
    {"Berlin", kShared + "/berlin_neukolln_2024.osm", false},
    {"NewYork", kShared + "/nyc_queens_village_2016.osm.pbf", false},
};

class EveryArea : public testing::TestWithParam<Extract> {};

} // namespace

TEST_P(EveryArea, MeshesOrIsCountedAsDropped) {
    const Extract& e = GetParam();
    if (!std::filesystem::exists(e.path)) {
        ASSERT_FALSE(e.required) << e.path << " is missing";
        GTEST_SKIP() << e.path << " not found (the shared data), skipping";
    }
    const CityModel city = importOsm(e.path, {});
    StreetMesh out;
    const auto start = std::chrono::steady_clock::now();
    meshGroundCover(city, {}, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    uint64_t dropped = 0;
    for (const auto& [reason, n] : out.dropped) {
        std::cout << e.name << ": dropped " << reason << " x" << n << "\n";
        if (reason != "area_hole_degenerate") dropped += n;
    }
    EXPECT_EQ(out.counts.at("ground_cover") + out.counts.at("water") + dropped, city.areas.size());
    EXPECT_EQ(droppedCount(out, "area_triangulation_failed"), 0u);
    EXPECT_EQ(out.objects, out.counts.at("ground_cover") + out.counts.at("water"));
    std::cout << e.name << ": " << city.areas.size() << " areas, " << out.mesh.size() << " triangles in " << seconds
              << " s\n";
}

INSTANTIATE_TEST_SUITE_P(Extracts, EveryArea, testing::ValuesIn(kExtracts),
                         [](const testing::TestParamInfo<Extract>& p) { return std::string(p.param.name); });
