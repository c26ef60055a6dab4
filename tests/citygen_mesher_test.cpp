// Building meshing: counts, closure and the courtyard hole. Walls large enough for a facade become
// procedural wall records (their triangle twin is tested in facade_twin_test.cpp).
#include "citygen/city_mesher.h"
#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <map>

using namespace urbis;
using urbis::test::openEdges;

namespace {

Building courtyardBuilding(float minHeight) {
    Building b;
    b.footprint.outer = {{0, 0}, {30, 0}, {30, 20}, {0, 20}};  // counter-clockwise
    b.footprint.holes = {{{10, 5}, {10, 15}, {20, 15}, {20, 5}}};  // clockwise
    b.minHeight = minHeight;
    b.height = 7.0f;  // below the parapet threshold: a plain flat roof
    return b;
}

} // namespace

TEST(BuildingMesher, CourtyardHasWallsRoofAndHole) {
    CityModel city;
    city.buildings = {courtyardBuilding(0.0f)};
    CityMesh out = meshCity(city);
    // 8 ring edges -> 8 procedural walls; a square annulus needs 8 roof triangles.
    EXPECT_EQ(out.walls.size(), 8u);
    EXPECT_EQ(out.trianglesByKind["walls"], 0u);
    EXPECT_EQ(out.trianglesByKind["roofs"], 8u);
    EXPECT_EQ(out.mesh.size(), 8u);
    // Courtyard walls face into the courtyard: their normals point away from its centre's far side.
    for (const WallRecord& w : out.walls) {
        const Vec3f mid = w.worldFromWall(0.5f * w.width, 0, 0);
        const bool courtyard = mid.x > 9.9f && mid.x < 20.1f && -mid.z > 4.9f && -mid.z < 15.1f;
        const Vec3f toCentre = Vec3f{15, 0, -10} - mid;
        EXPECT_EQ(dot(w.normal, toCentre) > 0.0f, courtyard) << "wall " << w.wallIndex;
    }
    // No roof triangle covers the courtyard's centre.
    for (size_t i = 0; i < out.mesh.size(); ++i) {
        const Triangle& t = out.mesh.triangles[i];
        if (t.p0.y != 7.0f || t.p1.y != 7.0f || t.p2.y != 7.0f) continue;
        Vec3f c = (t.p0 + t.p1 + t.p2) / 3.0f;
        EXPECT_FALSE(c.x > 10 && c.x < 20 && -c.z > 5 && -c.z < 15) << "roof over the hole";
    }
    EXPECT_FLOAT_EQ(out.cityBounds.hi.y, 7.0f);
}

TEST(BuildingMesher, FloatingPartIsClosed) {
    CityModel city;
    city.buildings = {courtyardBuilding(10.0f)};   // 2 m walls: too low for a facade, plain quads
    CityMesh out = meshCity(city);
    TriangleMesh building;
    for (size_t i = 0; i < out.mesh.size(); ++i)
        if (out.mesh.info[i].object == 1) building.add(out.mesh.triangles[i], out.mesh.info[i]);
    EXPECT_EQ(openEdges(building), 0u);
}

TEST(BuildingMesher, DegenerateFootprintIsCounted) {
    CityModel city;
    Building broken;
    broken.footprint.outer = {{0, 0}, {1, 1}};  // two points: not a polygon
    city.buildings = {courtyardBuilding(0.0f), broken};
    CityMesh out = meshCity(city);
    EXPECT_EQ(out.dropped["degenerate_footprint"], 1u);
    EXPECT_EQ(out.walls.size(), 8u);
}
