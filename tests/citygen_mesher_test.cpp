// Building meshing: counts, closure and the courtyard hole.
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
    // 8 ring edges -> 16 wall triangles; a square annulus needs 8 roof triangles.
    EXPECT_EQ(out.trianglesByKind["walls"], 16u);
    EXPECT_EQ(out.trianglesByKind["roofs"], 8u);
    EXPECT_EQ(out.mesh.size(), 16u + 8u);
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
    city.buildings = {courtyardBuilding(4.0f)};
    CityMesh out = meshCity(city);
    TriangleMesh building;
    for (size_t i = 0; i < out.mesh.size(); ++i)
        if (out.mesh.info[i].object == 1) building.add(out.mesh.triangles[i], out.mesh.info[i]);
    EXPECT_EQ(openEdges(building), 0u);
}

TEST(BuildingMesher, UntriangulableFootprintIsCounted) {
    CityModel city;
    Building broken;
    broken.footprint.outer = {{0, 0}, {1, 1}};  // two points: not a polygon
    city.buildings = {courtyardBuilding(0.0f), broken};
    CityMesh out = meshCity(city);
    EXPECT_EQ(out.dropped["triangulation_failed"], 1u);
    EXPECT_EQ(out.trianglesByKind["walls"], 16u);
}
