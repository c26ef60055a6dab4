// Rays aimed exactly at shared edges and vertices of closed meshes must never leak, through the 4-wide
// BVH and through the wide one with its block test in every instruction set.
#include "accel_test_scene.h"
#include "bvh4/build.h"
#include "bvh4/triangle_scene.h"
#include "geometry/wide_triangle_scene.h"
#include "scene/wide_triangle_scene_build.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace urbis;

namespace {

/// A closed box whose faces are n x n grids of quads, two triangles each, vertices shared;
/// rotated by rotation (rows) about the origin.
struct GridBox {
    std::vector<Vec3f> vertices;   ///< grid vertices, each shared by up to 6 triangles
    std::vector<Triangle> tris;
};

GridBox makeGridBox(int n, float halfSize, const Vec3f rotation[3]) {
    GridBox box;
    auto rotate = [&](Vec3f p) { return Vec3f{dot(rotation[0], p), dot(rotation[1], p), dot(rotation[2], p)}; };
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            auto at = [&](int i, int j) {
                Vec3f p;
                p[axis] = side * halfSize;
                p[(axis + 1) % 3] = -halfSize + 2.0f * halfSize * float(i) / float(n);
                p[(axis + 2) % 3] = -halfSize + 2.0f * halfSize * float(j) / float(n);
                return rotate(p);
            };
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) box.vertices.push_back(at(i, j));
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    // Alternate the diagonal so that vertices have valence 4 and 8.
                    if ((i + j) % 2 == 0) {
                        box.tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                        box.tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
                    } else {
                        box.tris.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                        box.tris.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
                    }
                }
        }
    return box;
}

/// Targets on shared features of the mesh: every vertex, and points on every edge.
std::vector<Vec3f> edgeAndVertexTargets(const std::vector<Triangle>& tris) {
    std::vector<Vec3f> targets;
    for (const Triangle& t : tris) {
        const Vec3f v[3] = {t.p0, t.p1, t.p2};
        for (int e = 0; e < 3; ++e) {
            targets.push_back(v[e]);
            for (float f : {0.5f, 0.25f, 0.1f}) targets.push_back(v[e] + (v[(e + 1) % 3] - v[e]) * f);
        }
    }
    return targets;
}

struct Scene {
    Bvh bvh;
    std::vector<Triangle> sorted;
    WideTriangleScene wide;
    TriangleSceneView view() const { return {bvh.nodes.data(), sorted.data(), uint32_t(sorted.size())}; }
};

Scene buildScene(const std::vector<Triangle>& tris) {
    Scene s;
    s.bvh = buildBvh(test::triangleBounds(tris));
    s.sorted = test::reorder(tris, s.bvh);
    s.wide = buildWideTriangleScene(tris);
    return s;
}

/// Whether the ray hits the closed mesh in every traversal: both BVHs, closest and any hit.
int leaksOf(const Scene& scene, const Ray& ray) {
    int leaks = !intersectClosest(scene.view(), ray).valid() + !occluded(scene.view(), ray);
    for (WideIsa isa : test::wideIsasHere())
        leaks += !traceWideTriangles(isa, scene.wide.view(), ray, false).valid() +
                 !traceWideTriangles(isa, scene.wide.view(), ray, true).valid();
    return leaks;
}

/// Every ray from origin through target (and slightly beyond) must hit the closed mesh.
void expectNoLeaks(const Scene& scene, Vec3f origin, const std::vector<Vec3f>& targets) {
    int leaks = 0;
    for (Vec3f target : targets) leaks += leaksOf(scene, Ray{origin, target - origin});
    EXPECT_EQ(leaks, 0) << "of " << targets.size() << " rays";
}

const Vec3f kIdentity[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

} // namespace

TEST(Watertight, AxisAlignedGridBoxFromInside) {
    const GridBox box = makeGridBox(8, 4.0f, kIdentity);
    const Scene scene = buildScene(box.tris);
    expectNoLeaks(scene, {0.0f, 0.0f, 0.0f}, edgeAndVertexTargets(box.tris));
    expectNoLeaks(scene, {0.3f, -1.7f, 2.1f}, edgeAndVertexTargets(box.tris));
}

TEST(Watertight, RotatedGridBoxFromManyOrigins) {
    const float c = std::cos(0.4f), s = std::sin(0.4f), c2 = std::cos(1.1f), s2 = std::sin(1.1f);
    // Rotation about z by 0.4 then about x by 1.1: no edge is axis-aligned.
    const Vec3f rot[3] = {{c, -s, 0.0f}, {c2 * s, c2 * c, -s2}, {s2 * s, s2 * c, c2}};
    const GridBox box = makeGridBox(6, 3.0f, rot);
    const Scene scene = buildScene(box.tris);
    const std::vector<Vec3f> targets = edgeAndVertexTargets(box.tris);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> inside(-1.5f, 1.5f);
    for (int i = 0; i < 8; ++i) expectNoLeaks(scene, {inside(rng), inside(rng), inside(rng)}, targets);
}

TEST(Watertight, FlatGridAndFansFromOutside) {
    // A planar grid of triangles (zero-thickness BVH bounds) and two closed fans around a
    // shared centre vertex: rays from above through any interior vertex or edge must hit.
    std::vector<Triangle> tris;
    std::vector<Vec3f> targets;
    constexpr int kN = 10;
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            const Vec3f a{float(i), 0.0f, float(j)}, b{float(i + 1), 0.0f, float(j)};
            const Vec3f c{float(i + 1), 0.0f, float(j + 1)}, d{float(i), 0.0f, float(j + 1)};
            tris.push_back({a, b, c});
            tris.push_back({a, c, d});
            if (i > 0 && j > 0) {
                targets.push_back(a);                       // vertex of valence 6
                targets.push_back((a + c) * 0.5f);          // diagonal edge
                targets.push_back(a + (b - a) * 0.3f);      // grid edge
            }
        }
    for (int fan = 0; fan < 2; ++fan) {
        const Vec3f centre{20.0f + 10.0f * fan, 3.0f, 5.0f};
        const int spokes = fan == 0 ? 7 : 32;
        for (int k = 0; k < spokes; ++k) {
            auto rim = [&](int m) {
                const float a = 6.2831853f * float(m % spokes) / float(spokes);
                return centre + Vec3f{4.0f * std::cos(a), 0.5f * std::sin(3.0f * a), 4.0f * std::sin(a)};
            };
            tris.push_back({centre, rim(k), rim(k + 1)});
            targets.push_back(centre + (rim(k) - centre) * 0.5f);
        }
        targets.push_back(centre);
    }
    const Scene scene = buildScene(tris);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> x(-20.0f, 50.0f), y(5.0f, 40.0f);
    for (int i = 0; i < 8; ++i) expectNoLeaks(scene, {x(rng), y(rng), x(rng)}, targets);
    // Straight down: axis-parallel directions exercise the zero-component inverse.
    int leaks = 0;
    for (Vec3f target : targets) leaks += leaksOf(scene, Ray{target + Vec3f{0.0f, 10.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
    EXPECT_EQ(leaks, 0);
}
