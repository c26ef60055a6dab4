// Roof shapes: watertight on every footprint kind, ridge direction, fallbacks, default heights.
#include "mesh_checks.h"
#include "layout/city_layout.h"
#include "osm/osm_import.h"
#include "roof_test_buildings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace urbis;
using namespace urbis::test;

namespace {

/// The spread (max - min) in world x and z of the roof's highest vertices.
std::pair<float, float> ridgeSpread(const TriangleMesh& mesh) {
    float top = -1e30f;
    for (const Triangle& t : mesh.triangles) top = std::max({top, t.p0.y, t.p1.y, t.p2.y});
    float x0 = 1e30f, x1 = -1e30f, z0 = 1e30f, z1 = -1e30f;
    for (const Triangle& t : mesh.triangles)
        for (const Vec3f& p : {t.p0, t.p1, t.p2})
            if (p.y == top) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
    return {x1 - x0, z1 - z0};
}

/// A generated city of 400 buildings, standing 0.5 m above the ground (so that each has a floor).
CityModel generatedCity() {
    LayoutParams params;
    params.buildings = 400;
    CityModel city = generateCity(params);
    for (Building& b : city.buildings) b.minHeight = 0.5f;
    return city;
}

/// How many of a city's buildings are not closed meshes.
size_t leakyBuildings(const CityMesh& out, size_t buildings) {
    std::vector<TriangleMesh> byBuilding(buildings);
    for (size_t i = 0; i < out.mesh.size(); ++i) byBuilding[out.mesh.info[i].object - 1].add(out.mesh.triangles[i], out.mesh.info[i]);
    size_t leaky = 0;
    for (const TriangleMesh& m : byBuilding) leaky += openEdges(m) != 0;
    return leaky;
}

} // namespace

TEST(RoofShapes, EveryShapeIsWatertightOnEveryFootprint) {
    const Polygon footprints[] = {rectangle(20, 10), lShape(), courtyard(), regularPolygon(24, 8), regularPolygon(5, 6)};
    for (const Polygon& footprint : footprints)
        for (RoofShape shape : kAllShapes)
            for (float roofHeight : {0.0f, 3.0f})  // default height and tagged height
                for (float height : {7.0f, 15.0f}) {  // 15 m: flat roofs get a parapet
                    const CityMesh out = meshOne(roofed(footprint, shape, 1.0f, height, roofHeight));
                    EXPECT_EQ(openEdges(out.mesh), 0u) << "shape " << int(shape) << " ring " << footprint.outer.size()
                                                       << " roof " << roofHeight << " height " << height;
                    EXPECT_GT(closedVolume(out.mesh), 0.0);
                    EXPECT_TRUE(out.dropped.empty());
                }
}

TEST(RoofShapes, RealVillageFootprintsAreWatertightWithEveryShape) {
    // The Bavarian village has no roof tags: every shape is forced on each footprint.
    const CityModel village = importOsm(URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm", ImportOptions{});
    ASSERT_GE(village.buildings.size(), 20u);
    for (RoofShape shape : kAllShapes) {
        size_t leaky = 0;
        std::map<std::string, uint64_t> fallbacks;
        for (Building b : village.buildings) {
            b.roofShape = shape;
            b.minHeight = 0.5f;
            const CityMesh out = meshOne(b);
            leaky += openEdges(out.mesh) != 0;
            for (const auto& [reason, n] : out.roofFallbacks) fallbacks[reason] += n;
        }
        EXPECT_EQ(leaky, 0u) << "shape " << int(shape);
        for (const auto& [reason, n] : fallbacks)
            EXPECT_TRUE(reason == "unknown_shape" || reason == "dome_not_round") << reason << " x" << n;
    }
}

TEST(RoofShapes, TheReadmeExampleHasEveryShapeWithoutAFallback) {
    // docs/examples/roof_shapes.osm, the README's roof picture: 15 buildings, each roof as tagged.
    CityModel example = importOsm(URBIS_EXAMPLES "/roof_shapes.osm", ImportOptions{});
    ASSERT_EQ(example.buildings.size(), 15u);
    std::set<RoofShape> shapes;
    for (Building& b : example.buildings) {
        shapes.insert(b.roofShape);
        b.minHeight = 0.5f;   // a floor, so that each building is a closed mesh
    }
    EXPECT_EQ(shapes.size(), 10u);
    const CityMesh out = meshCity(example, massModel());
    EXPECT_TRUE(out.roofFallbacks.empty()) << out.roofFallbacks.begin()->first;
    EXPECT_EQ(leakyBuildings(out, example.buildings.size()), 0u);
}

TEST(RoofShapes, GeneratedCityRoofsAreWatertight) {
    // The layout's houses have gabled and hipped roofs with a roof:direction toward their street.
    const CityModel city = generatedCity();
    size_t sloped = 0;
    for (const Building& b : city.buildings) sloped += b.roofShape != RoofShape::Flat;
    EXPECT_GT(sloped, 20u);
    const CityMesh out = meshCity(city, massModel());
    EXPECT_TRUE(out.roofFallbacks.empty());
    EXPECT_EQ(leakyBuildings(out, city.buildings.size()), 0u);
}

TEST(RoofShapes, GabledWingsAreWatertightOnGeneratedFootprints) {
    // The layout's L, T, U and courtyard footprints, gabled without a direction: a ridge and a gable
    // per wing (or a ridge all round a courtyard), never the one-ridge fallback, always closed.
    CityModel city = generatedCity();
    size_t wings = 0;
    for (Building& b : city.buildings) {
        b.roofShape = RoofShape::Gabled;
        b.roofDirection = -1;
        b.roofAcross = false;
        b.roofHeight = 0;
        wings += b.footprint.outer.size() > 4 || !b.footprint.holes.empty();
    }
    EXPECT_GT(wings, 20u);
    const CityMesh out = meshCity(city, massModel());
    EXPECT_TRUE(out.roofFallbacks.empty()) << out.roofFallbacks.begin()->first;
    EXPECT_EQ(leakyBuildings(out, city.buildings.size()), 0u);
}

TEST(RoofShapes, RidgeFollowsDirectionAndOrientation) {
    // 20 m east-west by 10 m north-south: by default the ridge runs along the long side (x).
    Building b = roofed(rectangle(20, 10), RoofShape::Gabled, 0, 10, 3);
    auto [dx, dz] = ridgeSpread(meshOne(b).mesh);
    EXPECT_NEAR(dx, 20, 1e-4);
    EXPECT_NEAR(dz, 0, 1e-4);
    // roof:orientation=across: along y.
    b.roofAcross = true;
    std::tie(dx, dz) = ridgeSpread(meshOne(b).mesh);
    EXPECT_NEAR(dx, 0, 1e-4);
    EXPECT_NEAR(dz, 10, 1e-4);
    // roof:direction=90: the slopes face east and west, so the ridge runs north-south.
    b.roofAcross = false;
    b.roofDirection = 90;
    std::tie(dx, dz) = ridgeSpread(meshOne(b).mesh);
    EXPECT_NEAR(dx, 0, 1e-4);
    EXPECT_NEAR(dz, 10, 1e-4);
    // A skillion facing south (180): its high side is the north edge (world z = -10).
    b.roofShape = RoofShape::Skillion;
    b.roofDirection = 180;
    std::tie(dx, dz) = ridgeSpread(meshOne(b).mesh);
    EXPECT_NEAR(dx, 20, 1e-4);
    EXPECT_NEAR(dz, 0, 1e-4);
    float topZ = 0;
    for (const Triangle& t : meshOne(b).mesh.triangles)
        if (t.p0.y == 10.0f) topZ = t.p0.z;
    EXPECT_FLOAT_EQ(topZ, -10.0f);
}

TEST(RoofShapes, UnknownShapeIsFlatAndCounted) {
    const CityMesh out = meshOne(roofed(rectangle(20, 10), RoofShape::Unknown, 0, 6, 0));
    EXPECT_EQ(out.roofFallbacks.at("unknown_shape"), 1u);
    EXPECT_FLOAT_EQ(out.cityBounds.hi.y, 6.0f);
    for (const Triangle& t : out.mesh.triangles)
        for (const Vec3f& p : {t.p0, t.p1, t.p2}) EXPECT_TRUE(p.y == 0.0f || p.y == 6.0f) << "not a flat box: " << p.y;
}

TEST(RoofShapes, DomeOnAnElongatedFootprintFallsBackToHipped) {
    const CityMesh out = meshOne(roofed(rectangle(30, 10), RoofShape::Dome, 0, 10, 3));
    EXPECT_EQ(out.roofFallbacks.at("dome_not_round"), 1u);
    EXPECT_FLOAT_EQ(out.cityBounds.hi.y, 10.0f);
}

TEST(RoofShapes, AngleAndDefaultPitchSetTheHeight) {
    // Gabled on a 10 m span: roof:angle 45 gives 5 m; untagged, 40 degrees gives 5 tan 40 = 4.20 m.
    Building b = roofed(rectangle(20, 10), RoofShape::Gabled, 0, 20, 0);
    b.roofAngle = 45;
    const CityMesh tagged = meshOne(b);
    float eaves = 20;
    for (const Triangle& t : tagged.mesh.triangles) eaves = std::min({eaves, t.p0.y > 0 ? t.p0.y : eaves});
    EXPECT_NEAR(eaves, 15.0f, 1e-4);
    b.roofAngle = -1;
    const CityMesh untagged = meshOne(b);
    eaves = 20;
    for (const Triangle& t : untagged.mesh.triangles) eaves = std::min({eaves, t.p0.y > 0 ? t.p0.y : eaves});
    EXPECT_NEAR(eaves, 20 - 5 * std::tan(40 * std::numbers::pi / 180), 1e-4);
}
