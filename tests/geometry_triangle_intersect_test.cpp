#include "geometry/triangle_intersect.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {
const Triangle kTri{{-1.0f, -1.0f, 2.0f}, {3.0f, -1.0f, 2.0f}, {-1.0f, 3.0f, 2.0f}};
}

TEST(TriangleIntersect, HitGivesDistanceAndBarycentrics) {
    Ray ray{{0.25f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    float t, u, v;
    ASSERT_TRUE(intersectTriangle(kTri, ray, t, u, v));
    EXPECT_FLOAT_EQ(t, 2.0f);
    const Vec3f p = kTri.p0 * (1.0f - u - v) + kTri.p1 * u + kTri.p2 * v;
    EXPECT_NEAR(p.x, 0.25f, 1e-6f);
    EXPECT_NEAR(p.y, 0.5f, 1e-6f);
}

TEST(TriangleIntersect, BothFacesHit) {
    Ray front{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    Ray back{{0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, -2.0f}};
    float t, u, v;
    EXPECT_TRUE(intersectTriangle(kTri, front, t, u, v));
    ASSERT_TRUE(intersectTriangle(kTri, back, t, u, v));
    EXPECT_FLOAT_EQ(t, 1.0f);   // in units of |dir| = 2
}

TEST(TriangleIntersect, MissesOutsideAndBehind) {
    float t, u, v;
    EXPECT_FALSE(intersectTriangle(kTri, Ray{{2.5f, 2.5f, 0.0f}, {0.0f, 0.0f, 1.0f}}, t, u, v));
    EXPECT_FALSE(intersectTriangle(kTri, Ray{{0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 1.0f}}, t, u, v));
}

TEST(TriangleIntersect, ParallelRayMisses) {
    float t, u, v;
    // Above the plane, parallel to it.
    EXPECT_FALSE(intersectTriangle(kTri, Ray{{-5.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}}, t, u, v));
    // In the plane, through the triangle: edge-on, no area seen, no hit.
    EXPECT_FALSE(intersectTriangle(kTri, Ray{{-5.0f, 0.0f, 2.0f}, {1.0f, 0.0f, 0.0f}}, t, u, v));
}

TEST(TriangleIntersect, IntervalIsOpenAtBothEnds) {
    float t, u, v;
    Ray ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    ray.tmin = 2.0f;   // hit exactly at tmin: excluded
    EXPECT_FALSE(intersectTriangle(kTri, ray, t, u, v));
    ray.tmin = 0.0f;
    ray.tmax = 2.0f;   // hit exactly at tmax: excluded
    EXPECT_FALSE(intersectTriangle(kTri, ray, t, u, v));
    ray.tmin = std::nextafter(2.0f, 0.0f);
    ray.tmax = std::nextafter(2.0f, 3.0f);
    EXPECT_TRUE(intersectTriangle(kTri, ray, t, u, v));
    EXPECT_EQ(t, 2.0f);
}

TEST(TriangleIntersect, DegenerateTrianglesNeverHit) {
    float t, u, v;
    const Ray ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    const Triangle collinear{{-1.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 2.0f}, {1.0f, 0.0f, 2.0f}};
    const Triangle point{{0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 2.0f}};
    const Triangle twoEqual{{0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 2.0f}, {1.0f, 1.0f, 2.0f}};
    EXPECT_FALSE(intersectTriangle(collinear, ray, t, u, v));
    EXPECT_FALSE(intersectTriangle(point, ray, t, u, v));
    EXPECT_FALSE(intersectTriangle(twoEqual, ray, t, u, v));
}

TEST(TriangleIntersect, EveryDominantAxisAndSign) {
    // The same geometry rotated onto each axis, seen from both sides.
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            auto place = [&](float a, float b, float c) {
                Vec3f p;
                p[axis] = c;
                p[(axis + 1) % 3] = a;
                p[(axis + 2) % 3] = b;
                return p;
            };
            const Triangle tri{place(-1, -1, 2), place(3, -1, 2), place(-1, 3, 2)};
            Vec3f dir;
            dir[axis] = sign;
            dir[(axis + 1) % 3] = 0.01f;
            Ray ray{place(0.0f, 0.0f, sign > 0 ? 0.0f : 4.0f), dir};
            float t, u, v;
            ASSERT_TRUE(intersectTriangle(tri, ray, t, u, v)) << axis << " " << sign;
            EXPECT_NEAR(t, 2.0f, 1e-5f);
        }
}
