// The 8-wide compressed BVH: its shape and conservative quantisation, a build the same for any
// thread count, its leaves in blocks, and closest hits equal to brute force and to the 4-wide BVH for
// every lane test and block test.
#include "accel/wide_bvh_build.h"
#include "accel/wide_lanes_avx2.h"
#include "accel/wide_leaf_groups.h"
#include "accel_test_scene.h"
#include "bvh4/build.h"
#include "bvh4/triangle_scene.h"
#include "citygen/city_mesher.h"
#include "geometry/wide_triangle_scene.h"
#include "osm/osm_import.h"
#include "scene/wide_triangle_scene_build.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <filesystem>

using namespace urbis;

namespace {

const char* isaName(WideIsa isa) { return isa == WideIsa::Scalar ? "scalar" : isa == WideIsa::Sse ? "SSE" : "AVX2"; }

/// A traversal of the wide triangle scene with one lane test and one block test.
struct WideTracer {
    const char* name;   ///< lane test / block test
    Hit (*trace)(const WideTriangleSceneView&, Ray, bool);
};

/// Every pairing of lane test and block test this CPU runs; the first is the scalar reference.
std::vector<WideTracer> tracersHere() {
    std::vector<WideTracer> tracers{{"scalar/scalar", traceWideTriangles<WideLanesScalar, TriangleBlockScalar>}};
#if URBIS_HAVE_SSE
    tracers.push_back({"scalar/SSE", traceWideTriangles<WideLanesScalar, TriangleBlockSse>});
    tracers.push_back({"SSE/scalar", traceWideTriangles<WideLanesSse, TriangleBlockScalar>});
    tracers.push_back({"SSE/SSE", traceWideTriangles<WideLanesSse, TriangleBlockSse>});
    if (hostWideIsa() == WideIsa::Avx2) tracers.push_back({"AVX2/SSE in AVX2", traceWideTrianglesAvx2});
#endif
    return tracers;
}

unsigned lanesWith(WideIsa isa, const WideBvhNode& node, const BvhRay& r, const Ray& ray, float (&tEntry)[kWideBvhWidth]) {
#if URBIS_HAVE_SSE
    if (isa == WideIsa::Avx2) return WideLanesAvx2::test(node, r, ray.tmin, ray.tmax, tEntry);
    if (isa == WideIsa::Sse) return WideLanesSse::test(node, r, ray.tmin, ray.tmax, tEntry);
#endif
    return WideLanesScalar::test(node, r, ray.tmin, ray.tmax, tEntry);
}

/// Every primitive in exactly one leaf, inside its leaf's decoded box and inside every decoded box
/// above it (the quantisation is conservative; a child's decoded box, on its own grid, may reach
/// past its parent's); leaves within the size limit; depth under 64.
void expectWellFormed(const WideBvh& bvh, const std::vector<Bounds3f>& primBounds, uint32_t maxLeafSize) {
    std::vector<int> seen(primBounds.size(), 0);
    test::TreeWalk walk;
    for (test::TreeWalk::Item it; walk.next(it);) {
        ASSERT_LT(it.node, bvh.nodes.size());
        const WideBvhNode& n = bvh.nodes[it.node];
        uint32_t slot = n.primBase, child = n.childBase;
        for (int l = 0; l < kWideBvhWidth; ++l) {
            const Bounds3f box = decodedBox(n, l);
            const bool inner = n.innerMask >> l & 1u;
            if (!inner && n.leafSize(l) == 0) {
                EXPECT_GT(n.q[0][l], n.q[3][l]) << "an unused lane's box is empty";
                continue;
            }
            const Bounds3f within{vmax(box.lo, it.box.lo), vmin(box.hi, it.box.hi)};
            if (inner) {
                walk.push(child++, it, within);
                continue;
            }
            EXPECT_LE(n.leafSize(l), maxLeafSize);
            for (uint32_t i = slot; i < slot + n.leafSize(l); ++i) {
                ++seen[bvh.primOrder[i]];
                EXPECT_TRUE(test::inside(primBounds[bvh.primOrder[i]], within)) << "prim " << bvh.primOrder[i];
            }
            slot += n.leafSize(l);
        }
    }
    for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << i;
    EXPECT_LT(walk.maxDepth, 64u);
}

/// Downtown San Francisco as the benchmarks mesh it (plain walls), or nothing without the shared data.
std::vector<Triangle> sanFrancisco() {
    const std::string path = URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf";
    if (!std::filesystem::exists(path)) return {};
    CityMeshOptions options;
    options.geometry.walls = Representation::Plain;
    return meshCity(importOsm(path, ImportOptions{}), options).mesh.triangles;
}

/// Whether two distances agree: equal, or within 1e-6 relative, since a triangle that lies in a face
/// of its box may be found a few ulps nearer than the box is entered and then be culled by one tree
/// and not by another (or by brute force), as it can be in the 4-wide BVH.
bool sameDistance(const Hit& a, const Hit& b) {
    return a.valid() == b.valid() && (!a.valid() || std::fabs(a.t - b.t) <= 1e-6f * b.t);
}

/// Traces `rays` through the wide BVH with every lane test and block test this CPU has and expects
/// the same hits, bit for bit, and the closest hit and any-hit answers of the checked 4-wide BVH (sameDistance; the
/// same triangle unless two tie at that distance, on a shared edge). Every `bruteForceEvery`-th ray
/// is also checked against brute force. Returns the number of hits.
size_t expectSameHits(const std::vector<Triangle>& tris, const std::vector<Ray>& rays, size_t bruteForceEvery) {
    const std::vector<Bounds3f> bounds = test::triangleBounds(tris);
    const Bvh narrow = buildBvh(bounds);
    const WideTriangleScene wide = buildWideTriangleScene(tris);
    const std::vector<Triangle> narrowTris = test::reorder(tris, narrow);
    const TriangleSceneView narrowView{narrow.nodes.data(), narrowTris.data(), uint32_t(narrowTris.size())};
    const WideTriangleSceneView wideView = wide.view();
    const std::vector<WideTracer> tracers = tracersHere();
    std::atomic<size_t> hits{0}, exact{0}, tMismatch{0}, primMismatch{0}, anyMismatch{0}, isaMismatch{0}, bruteMismatch{0};
    tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
        const Hit reference = intersectClosest(narrowView, rays[i]);
        const Hit got = tracers[0].trace(wideView, rays[i], false);
        for (const WideTracer& tracer : tracers) {
            const Hit other = tracer.trace(wideView, rays[i], false);
            if (std::memcmp(&other, &got, sizeof(Hit)) != 0) ++isaMismatch;
            if (tracer.trace(wideView, rays[i], true).valid() != got.valid()) ++anyMismatch;
        }
        if (!sameDistance(got, reference)) ++tMismatch;
        if (got.valid() && reference.valid()) {
            ++hits;
            exact += got.t == reference.t;
            if (wide.bvh.primOrder[got.prim] != narrow.primOrder[reference.prim] && got.t != reference.t) ++primMismatch;
        }
        if (i % bruteForceEvery == 0 && !sameDistance(got, test::bruteForce(tris, rays[i]))) ++bruteMismatch;
    });
    EXPECT_EQ(isaMismatch, 0u);
    EXPECT_EQ(anyMismatch, 0u);
    EXPECT_EQ(tMismatch, 0u);
    EXPECT_LE(primMismatch, hits / 10000) << "different triangles only at (almost) equal distances";
    EXPECT_GE(exact, hits - hits / 10000) << "distances equal but for a few in 10^4";
    EXPECT_EQ(bruteMismatch, 0u);
    return hits;
}

} // namespace

TEST(WideBvhBuild, EmptyInputIsNeverHit) {
    const WideBvh bvh = buildWideBvh({});
    ASSERT_EQ(bvh.nodes.size(), 1u);
    const WideTriangleScene scene = buildWideTriangleScene({});
    ASSERT_TRUE(scene.blocks.empty());
    for (const WideTracer& tracer : tracersHere())
        EXPECT_FALSE(tracer.trace(scene.view(), Ray{{0, 1, 0}, {0, -1, 0}}, false).valid()) << tracer.name;
}

TEST(WideBvhBuild, WellFormedAndConservativeForSeveralOptions) {
    const std::vector<Bounds3f> bounds = test::triangleBounds(test::makeCityScene(3));
    for (uint32_t leaf : {1u, 2u, 4u, 8u, 15u}) {
        BvhBuildOptions options;
        options.maxLeafSize = leaf;
        SCOPED_TRACE(leaf);
        expectWellFormed(buildWideBvh(bounds, options), bounds, leaf);
        options.leafGroupSize = 4;   // the SAH counting blocks of four, as buildWideTriangleScene builds it
        expectWellFormed(buildWideBvh(bounds, options), bounds, leaf);
    }
    // Far from the origin, where a float's step is coarse, and in a box of zero extent on one axis.
    std::vector<Bounds3f> far = bounds;
    for (Bounds3f& b : far) {
        b.lo = b.lo + Vec3f{3.0e5f, 0.0f, -7.0e5f};
        b.hi = b.hi + Vec3f{3.0e5f, 0.0f, -7.0e5f};
        b.lo.y = b.hi.y = 2.0f;
    }
    expectWellFormed(buildWideBvh(far), far, BvhBuildOptions{}.maxLeafSize);
}

TEST(WideBvhBuild, SameNodesForAnyThreadCount) {
    const std::vector<Bounds3f> bounds = test::triangleBounds(test::makeCityScene(7, 6000, 2000));
    auto build = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        BvhBuildOptions options;
        options.parallelThreshold = 256;
        return buildWideBvh(bounds, options);
    };
    const WideBvh one = build(1);
    for (int threads : {2, 4}) {
        const WideBvh many = build(threads);
        ASSERT_EQ(one.nodes.size(), many.nodes.size());
        EXPECT_EQ(0, std::memcmp(one.nodes.data(), many.nodes.data(), one.nodes.size() * sizeof(WideBvhNode)));
        EXPECT_EQ(one.primOrder, many.primOrder);
    }
}

TEST(WideBvhBuild, CostlyPrimitivesGetMarkedLeavesOfTheirOwn) {
    std::vector<Bounds3f> walls;
    for (int i = 0; i < 40; ++i) walls.push_back({{float(i), 0.0f, 0.0f}, {float(i) + 0.9f, 10.0f, 0.2f}});
    std::vector<uint32_t> costs(walls.size(), 16u);
    costs[5] = 1u;   // one cheap primitive among them
    const WideBvh bvh = buildWideBvh(walls, BvhBuildOptions{}, costs);
    expectWellFormed(bvh, walls, BvhBuildOptions{}.maxLeafSize);
    int costly = 0, cheap = 0;
    for (const WideBvhNode& n : bvh.nodes) {
        uint32_t slot = n.primBase;
        for (int l = 0; l < kWideBvhWidth; ++l) {
            if (n.leafSize(l) == 0) continue;
            EXPECT_EQ(n.leafSize(l), 1u);
            EXPECT_EQ(n.costlyLeaf(l), costs[bvh.primOrder[slot]] > 1);
            (n.costlyLeaf(l) ? costly : cheap) += 1;
            slot += n.leafSize(l);
        }
    }
    EXPECT_EQ(costly, 39);
    EXPECT_EQ(cheap, 1);
}

TEST(WideBvhTraverse, LaneTestsAgreeBitForBit) {
    const std::vector<Triangle> tris = test::makeCityScene(11);
    const WideBvh bvh = buildWideBvh(test::triangleBounds(tris));
    Bounds3f box;
    for (const Triangle& t : tris) box.extend(t.p0);
    std::vector<Ray> rays = test::cityRays(tris, box, 20.0f, 2000, 4);
    // Along the axes too: direction components of zero, whose inverses are +-FLT_MAX.
    for (size_t i = 0; i < rays.size(); i += 5) rays[i].dir = {i % 2 ? 0.0f : -0.0f, -1.0f, 0.0f};
    for (size_t i = 1; i < rays.size(); i += 5) rays[i].dir = {i % 3 ? 1.0f : -1.0f, 0.0f, 0.0f};
    int compared = 0;
    for (const Ray& ray : rays) {
        const BvhRay r(ray);
        for (size_t n = 0; n < bvh.nodes.size(); n += 7) {
            float expected[kWideBvhWidth];
            const unsigned expectedMask = lanesWith(WideIsa::Scalar, bvh.nodes[n], r, ray, expected);
            for (WideIsa isa : test::wideIsasHere()) {
                float got[kWideBvhWidth];
                ASSERT_EQ(lanesWith(isa, bvh.nodes[n], r, ray, got), expectedMask) << isaName(isa) << " node " << n;
                for (int l = 0; l < kWideBvhWidth; ++l)
                    if (expectedMask >> l & 1u) {
                        ASSERT_EQ(std::memcmp(&got[l], &expected[l], sizeof(float)), 0) << isaName(isa);
                    }
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 0);
}

TEST(WideBvhTraverse, ClosestHitsEqualBruteForceOnAGeneratedCity) {
    const std::vector<Triangle> tris = test::makeCityScene(5);
    const std::vector<Ray> rays = test::cityRays(tris, test::kCitySceneRayBox, 20.0f, 100000, 9);
    EXPECT_GT(expectSameHits(tris, rays, 2), 50000u);
}

TEST(WideBvhTraverse, ClosestHitsEqualOnSanFrancisco) {
    const std::vector<Triangle> tris = sanFrancisco();
    if (tris.empty()) GTEST_SKIP() << URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf not found (the shared data), skipping";
    Bounds3f box;
    for (const Triangle& t : tris) {
        box.extend(t.p0);
        box.extend(t.p1);
        box.extend(t.p2);
    }
    box.hi.y = 2.0f * box.hi.y;
    // 100k rays against the 4-wide BVH (itself checked against brute force), one in 200 against brute force too.
    const std::vector<Ray> rays = test::cityRays(tris, box, 0.25f * box.extent().y, 100000, 21);
    EXPECT_GT(expectSameHits(tris, rays, 200), 30000u);
}
