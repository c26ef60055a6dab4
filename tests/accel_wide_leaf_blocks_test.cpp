// The wide BVH's leaves in groups (groupWideLeaves) and their triangles in blocks: every leaf's
// primitives exactly once, in order, and the SSE block test equal to the scalar one bit for bit.
#include "accel/wide_leaf_groups.h"
#include "accel_test_scene.h"
#include "geometry/triangle_block_sse.h"
#include "scene/wide_triangle_scene_build.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace urbis;

TEST(WideLeafGroups, EachLeafSplitInOrderIntoGroups) {
    const std::vector<Bounds3f> bounds = test::triangleBounds(test::makeCityScene(3));
    for (uint32_t leaf : {1u, 4u, 8u, 15u}) {
        for (uint32_t width : {1u, 4u, 8u}) {
            SCOPED_TRACE(testing::Message() << "leaf " << leaf << ", width " << width);
            BvhBuildOptions options;
            options.maxLeafSize = leaf;
            const WideBvh before = buildWideBvh(bounds, options);
            WideBvh after = before;
            const std::vector<WideLeafGroup> groups = groupWideLeaves(after, width);
            ASSERT_EQ(after.nodes.size(), before.nodes.size());
            uint32_t nextPrim = 0;   // groups follow primOrder
            for (const WideLeafGroup& g : groups) {
                ASSERT_EQ(g.first, nextPrim);
                ASSERT_GE(g.count, 1u);
                ASSERT_LE(g.count, width);
                nextPrim += g.count;
            }
            EXPECT_EQ(nextPrim, before.primOrder.size());
            for (size_t n = 0; n < before.nodes.size(); ++n) {
                const WideBvhNode &b = before.nodes[n], &a = after.nodes[n];
                EXPECT_EQ(std::memcmp(b.q, a.q, sizeof(b.q)), 0);
                EXPECT_EQ(a.innerMask, b.innerMask);
                uint32_t prim = b.primBase, group = a.primBase;
                for (int l = 0; l < kWideBvhWidth; ++l) {
                    EXPECT_EQ(a.costlyLeaf(l), b.costlyLeaf(l));
                    EXPECT_EQ(a.leafSize(l), (b.leafSize(l) + width - 1) / width);
                    uint32_t covered = 0;
                    for (uint32_t i = 0; i < a.leafSize(l); ++i, ++group) {
                        ASSERT_LT(group, groups.size());
                        EXPECT_EQ(groups[group].first, prim + covered);
                        covered += groups[group].count;
                    }
                    EXPECT_EQ(covered, b.leafSize(l));
                    prim += b.leafSize(l);
                }
            }
        }
    }
}

TEST(WideLeafGroups, SahCountingGroupsFillsThem) {
    const std::vector<Bounds3f> bounds = test::triangleBounds(test::makeCityScene(6));
    auto groupsWith = [&](uint32_t leafGroupSize) {
        BvhBuildOptions options;
        options.leafGroupSize = leafGroupSize;
        WideBvh bvh = buildWideBvh(bounds, options);
        return groupWideLeaves(bvh, 4).size();
    };
    const size_t perPrimitive = groupsWith(1), perGroup = groupsWith(4);
    EXPECT_LT(perGroup, perPrimitive);
    EXPECT_GT(double(bounds.size()) / double(perGroup), 2.5) << "triangles per group";
}

TEST(WideLeafGroups, BlocksHoldTheLeafTrianglesAndRepeatTheLast) {
    const std::vector<Triangle> tris = test::makeCityScene(4, 300, 200);
    const WideTriangleScene scene = buildWideTriangleScene(tris);
    std::vector<int> seen(tris.size(), 0);
    for (const TriangleBlock& block : scene.blocks) {
        for (int l = 0; l < kTriangleBlockWidth; ++l) {
            const Triangle t = block.triangle(l), &expected = scene.triangles[block.prim[l]];
            EXPECT_EQ(std::memcmp(&t, &expected, sizeof(Triangle)), 0);
            // Lanes hold consecutive triangles, a short block repeating its last one.
            if (l > 0) {
                EXPECT_TRUE(block.prim[l] == block.prim[l - 1] + 1 || block.prim[l] == block.prim[l - 1]);
            }
            if (l == 0 || block.prim[l] != block.prim[l - 1]) ++seen[block.prim[l]];
        }
    }
    for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << i;
}

#if URBIS_HAVE_SSE
TEST(TriangleBlock, SseTestAgreesWithScalarBitForBit) {
    const std::vector<Triangle> tris = test::makeCityScene(9, 300, 200);
    const WideTriangleScene scene = buildWideTriangleScene(tris);
    std::vector<Ray> rays = test::cityRays(tris, test::kCitySceneRayBox, 20.0f, 300, 5);
    int hits = 0, compared = 0;
    for (size_t b = 0; b < scene.blocks.size(); b += 3) {
        const TriangleBlock& block = scene.blocks[b];
        // Also at the block's own vertices and edges, where edge functions are zero in float (the
        // double fallback), and along the axes, from the first ray origins.
        std::vector<Ray> own;
        for (int l = 0; l < kTriangleBlockWidth; ++l) {
            const Triangle t = block.triangle(l);
            const Vec3f o = rays[l].origin;
            own.push_back({o, t.p0 - o});
            own.push_back({o, (t.p1 + t.p2) * 0.5f - o});
            own.push_back({t.p0 + Vec3f{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
            own.push_back({(t.p0 + t.p1) * 0.5f + Vec3f{3.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}});
        }
        for (size_t i = 0; i < rays.size() + own.size(); ++i) {
            const Ray ray = i < rays.size() ? rays[i] : own[i - rays.size()];
            const WatertightRay wr(ray);
            Ray scalarRay = ray, sseRay = ray;
            Hit scalarHit, sseHit;
            const bool scalar = TriangleBlockScalar::hit(block, wr, scalarRay, scalarHit);
            ASSERT_EQ(TriangleBlockSse::hit(block, wr, sseRay, sseHit), scalar) << "block " << b << " ray " << i;
            EXPECT_EQ(std::memcmp(&scalarHit, &sseHit, sizeof(Hit)), 0) << "block " << b << " ray " << i;
            EXPECT_EQ(std::memcmp(&scalarRay.tmax, &sseRay.tmax, sizeof(float)), 0);
            hits += scalar;
            ++compared;
        }
    }
    EXPECT_GT(hits, 1000);   // the rays aimed at the blocks' own edges, mostly
}
#endif
