// Early split clipping of street triangles (accel/split_references, Scene::build): the pieces' boxes
// cover the triangle and are much smaller than its box, and traces over a scene of diagonal streets
// among boxes find what brute force over every triangle and the ground finds.
#include "accel_test_scene.h"

#include "accel/split_references.h"
#include "geometry/scene_intersect.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

using namespace urbis;

namespace {

bool inside(const Bounds3f& b, Vec3f p) {
    return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

/// A 40 m x 3 m sidewalk top at 0.25 m and its 13 cm curb face, along a 45-degree street through (x, z).
void appendDiagonalStreet(std::vector<Triangle>& out, float x, float z) {
    const float c = std::sqrt(0.5f);
    const Vec3f along{40.0f * c, 0, 40.0f * c}, across{-3.0f * c, 0, 3.0f * c};
    const Vec3f a{x, 0.25f, z}, b = a + along, d = a + across, e = b + across;
    out.push_back({a, b, e});
    out.push_back({a, e, d});
    const Vec3f down{0, -0.13f, 0};
    out.push_back({a + down, b + down, b});
    out.push_back({a + down, b, a});
}

/// The nearest triangle or ground hit by testing every one: t, and whether it is the ground's.
std::pair<float, bool> bruteForce(const Scene& scene, const Ray& ray) {
    float best = ray.tmax;
    bool ground = false;
    const float t = (scene.grounds[0].height - ray.origin.y) / ray.dir.y;
    if (ray.dir.y != 0.0f && t > ray.tmin && t < best) best = t, ground = true;
    for (const Triangle& tri : scene.triangles) {
        float hit, u, v;
        Ray r = ray;
        r.tmax = best;
        if (intersectTriangle(tri, r, hit, u, v)) best = hit, ground = false;
    }
    return {best, ground};
}

} // namespace

TEST(SplitReferences, PiecesCoverTheTriangleInLessArea) {
    const float c = std::sqrt(0.5f);
    const Vec3f a{100, 0.12f, -50}, b = a + Vec3f{40 * c, 0, 40 * c}, d = a + Vec3f{-3 * c, 0, 3 * c};
    std::vector<Bounds3f> pieces;
    splitTriangleBounds(a, b, d, SplitOptions{}, pieces);
    ASSERT_GT(pieces.size(), 4u);
    Bounds3f whole;
    whole.extend(a), whole.extend(b), whole.extend(d);
    float area = 0;
    for (const Bounds3f& p : pieces) {
        area += p.area();
        EXPECT_TRUE(inside(whole, p.lo) && inside(whole, p.hi));
    }
    EXPECT_LT(area, 0.5f * whole.area());
    // Every point of the triangle (a grid of barycentrics, edges included) lies in some piece.
    constexpr int kSteps = 200;
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; i + j <= kSteps; ++j) {
            const float u = float(i) / kSteps, v = float(j) / kSteps;
            const Vec3f p = a + (b - a) * u + (d - a) * v;
            bool covered = false;
            for (const Bounds3f& piece : pieces) covered |= inside(piece, p);
            EXPECT_TRUE(covered) << u << " " << v;
        }
    // A triangle that fills half its box is not worth splitting.
    pieces.clear();
    splitTriangleBounds({0, 0, 0}, {10, 0, 0}, {0, 0, 10}, SplitOptions{}, pieces);
    EXPECT_EQ(pieces.size(), 1u);
}

TEST(SplitReferences, TracesOverDiagonalStreetsEqualBruteForce) {
    std::vector<Triangle> tris = test::makeCityScene(7, 300, 100);
    const size_t firstStreet = tris.size();
    for (int i = 0; i < 60; ++i) appendDiagonalStreet(tris, -100.0f + 3.3f * float(i), -100.0f + 2.1f * float(i % 17) * 5.0f);
    TriangleMesh mesh;
    for (const Triangle& t : tris) mesh.add(t, TriangleInfo{0, 1, uint32_t(SurfacePart::Road)});
    const Scene scene = Scene::build({.mesh = mesh, .materials = std::vector<Material>(1),
                                      .grounds = {GroundRecord::around(0, 0, -0.05f, 0)}});
    // The streets' triangles have several references each, so several records.
    EXPECT_GT(scene.triangles.size(), tris.size() + (tris.size() - firstStreet));
    const SceneView view = scene.view();
    EXPECT_EQ(view.kindEnd[0], uint32_t(scene.triangles.size()));
    constexpr uint32_t kRays = 20000;
    uint32_t hits = 0, mismatches = 0;
    for (uint32_t i = 0; i < kRays; ++i) {
        SampleStream rng{777u, i, 0};
        // Origins over and among the boxes, half of them just above the streets (as rays leaving a
        // street do); directions uniform.
        const Vec3f o{240.0f * rng.draw() - 120.0f, i % 2 ? 0.26f + 0.5f * rng.draw() : 80.0f * rng.draw(),
                      240.0f * rng.draw() - 120.0f};
        const float z = 2.0f * rng.draw() - 1.0f, phi = 2.0f * kPi * rng.draw(), s = std::sqrt(1.0f - z * z);
        const Ray ray{o, {s * std::cos(phi), z, s * std::sin(phi)}};
        const SurfaceHit got = intersectScene(view, ray);
        const auto [t, ground] = bruteForce(scene, ray);
        ASSERT_EQ(got.valid(), t < ray.tmax) << "ray " << i;
        EXPECT_EQ(occludedScene(view, ray), got.valid()) << "ray " << i;
        if (!got.valid()) continue;
        ++hits;
        if (got.kind != (ground ? kPrimKindOf<GroundRecord> : kPrimKindOf<Triangle>) || std::abs(got.t - t) > 1e-5f * t) ++mismatches;
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(hits, kRays / 2);
}
