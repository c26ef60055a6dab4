// The water's bed (streets/water_depth.h): the depth profile, and the mesh of a square pond whose
// distance to the shore is known exactly at every point.
#include "streets/ground_cover_shapes.h"
#include "streets/water_depth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace urbis;

TEST(WaterBed, DepthFallsFromTheShoreToTheShelfAndStays) {
    WaterOptions o;
    o.maxDepth = 4.0f;
    o.shelfWidth = 20.0f;
    EXPECT_FLOAT_EQ(waterBedDepth(0.0, o), kMinBedDepth);
    EXPECT_FLOAT_EQ(waterBedDepth(10.0, o), 3.0f) << "1 - (1 - 1/2)^2 of the depth at half the shelf";
    EXPECT_FLOAT_EQ(waterBedDepth(20.0, o), 4.0f);
    EXPECT_FLOAT_EQ(waterBedDepth(500.0, o), 4.0f);
    for (double d = 0; d < 30; d += 0.5) EXPECT_LE(waterBedDepth(d, o), waterBedDepth(d + 0.5, o));
    o.shelfWidth = 0.0f;
    EXPECT_FLOAT_EQ(waterBedDepth(0.0, o), 4.0f) << "no shelf: a wall at the shore";
}

// A 100 m square pond: its bed covers the pond exactly (projected area 10,000 m^2 to 1e-6), every
// vertex lies at the depth of its distance to the nearest side (to 1 mm), the shore's vertices at the
// shallowest depth, the middle at the deepest.
TEST(WaterBed, SquarePondBedFollowsTheDistanceToTheShore) {
    CoverShapes shapes;
    Polygon square;
    square.outer = {{-50, -50}, {50, -50}, {50, 50}, {-50, 50}};
    ASSERT_EQ(shapes.add(square), CoverShapes::Added::Shape);
    WaterOptions o;
    TriangleMesh mesh;
    const size_t n = meshWaterBed(shapes, 0, o, TriangleInfo{3, 1, 0}, mesh);
    ASSERT_GT(n, 0u);
    ASSERT_EQ(mesh.size(), n);
    double projected = 0;
    float deepest = 0, shallowest = -1e9f;
    for (const Triangle& t : mesh.triangles) {
        const Vec3f a = t.p0, b = t.p1, c = t.p2;
        projected += 0.5 * std::fabs(double(b.x - a.x) * double(c.z - a.z) - double(c.x - a.x) * double(b.z - a.z));
        for (const Vec3f v : {a, b, c}) {
            const double toShore = std::min({50.0 - std::fabs(double(v.x)), 50.0 - std::fabs(double(v.z))});
            EXPECT_NEAR(-v.y, waterBedDepth(toShore, o), 1e-3) << v.x << ", " << v.z;
            deepest = std::min(deepest, v.y);
            shallowest = std::max(shallowest, v.y);
        }
    }
    EXPECT_NEAR(projected, 10000.0, 1e-6 * 10000.0);
    EXPECT_FLOAT_EQ(deepest, -o.maxDepth);
    EXPECT_FLOAT_EQ(shallowest, -kMinBedDepth);
    // Cells of at most half the shelf near the shore (halvings of the box: 6.25 m), larger in the
    // middle: fewer triangles than a uniform grid of those cells (16^2 x 2).
    EXPECT_LT(n, size_t(16 * 16 * 2));
}
