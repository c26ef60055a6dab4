// The scene's BVH over a real imported city against brute force: 100k random rays, same triangle and distance.
#include "citygen/city_mesher.h"
#include "geometry/scene_intersect.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "osm/osm_import.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

Hit bruteForce(const Scene& scene, const Ray& ray) {
    Hit best;
    float tmax = ray.tmax;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        float t, u, v;
        Ray r = ray;
        r.tmax = tmax;
        if (intersectTriangle(scene.triangles[i], r, t, u, v)) {
            best = {i, t, u, v};
            tmax = t;
        }
    }
    return best;
}

/// The city's triangles, with each procedural wall as the plain quad of its wall plane: a
/// triangle-only scene of the real city's shape.
TriangleMesh plainCity(const CityMesh& mesh) {
    TriangleMesh out = mesh.mesh;
    for (const WallRecord& w : mesh.walls) {
        const Vec3f a = w.worldFromWall(0, 0, 0), b = w.worldFromWall(w.width, 0, 0);
        const Vec3f c = w.worldFromWall(w.width, w.height, 0), d = w.worldFromWall(0, w.height, 0);
        out.add({a, b, c}, {});
        out.add({a, c, d}, {});
    }
    return out;
}

} // namespace

TEST(AccelRealCity, SceneHitsEqualBruteForceOnTheBavarianVillage) {
    CityModel city = importOsm(URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm", ImportOptions{});
    CityMesh mesh = meshCity(city);
    Scene scene = Scene::build({.mesh = plainCity(mesh), .materials = mesh.materials});
    ASSERT_GT(scene.triangles.size(), 500u);
    const SceneView view = scene.view();
    Bounds3f b = mesh.cityBounds;
    size_t hits = 0, mismatches = 0;
    constexpr uint32_t kRays = 100000;
    for (uint32_t i = 0; i < kRays; ++i) {
        SampleStream rng{12345u, i, 0};
        // Origins in a box 20% larger than the city and up to twice its height; directions uniform
        // for even rays, aimed at a random triangle's centroid for odd ones.
        Vec3f o{b.lo.x + (1.4f * rng.draw() - 0.2f) * b.extent().x, 2.0f * rng.draw() * b.hi.y,
                b.lo.z + (1.4f * rng.draw() - 0.2f) * b.extent().z};
        float z = 2.0f * rng.draw() - 1.0f, phi = 2.0f * kPi * rng.draw(), s = std::sqrt(1.0f - z * z);
        Vec3f dir{s * std::cos(phi), z, s * std::sin(phi)};
        if (i % 2) {
            const Triangle& t = scene.triangles[uint32_t(rng.draw() * float(scene.triangles.size()))];
            dir = normalize((t.p0 + t.p1 + t.p2) / 3.0f - o);
        }
        Ray ray{o, dir};
        const SurfaceHit fast = intersectScene(view, ray);
        const Hit slow = bruteForce(scene, ray);
        ASSERT_EQ(fast.valid(), slow.valid()) << "ray " << i;
        EXPECT_EQ(occludedScene(view, ray), slow.valid()) << "ray " << i;
        if (!slow.valid()) continue;
        ++hits;
        // Equal distances may belong to two triangles sharing the hit edge: then either is right.
        if (fast.index != slow.prim && fast.t != slow.t) ++mismatches;
        EXPECT_NEAR(fast.t, slow.t, 1e-6f * slow.t) << "ray " << i;
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(hits, kRays / 3);
}
