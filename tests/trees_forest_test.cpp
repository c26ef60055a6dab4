// The forest by domain repetition (scene/forest_record.h, geometry/forest_intersect.h): the ray's
// cell walk finds every tree that a test of every cell's tree finds, at the same distance; every tree
// fits the reach the walk assumes; the forest's memory does not grow with its area; and through a
// scene, a forest runs to the horizon at street level and covers the ground seen from above.
#include "accel/bvh_traverse.h"
#include "geometry/scene_intersect.h"
#include "nature/forest_records.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "scene/tree_shape.h"
#include "tree_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace urbis;

namespace {

/// The nearest hit of `ray` over every tree of `forest`, each tested over the whole ray.
bool bruteForce(const ForestRecord& f, const Ray& ray, float& tHit) {
    const BvhRay bvh(ray);
    bool found = false;
    tHit = ray.tmax;
    for (int32_t k = int32_t(std::floor(f.z0 / f.cell)); k <= int32_t(std::floor(f.z1 / f.cell)); ++k)
        for (int32_t i = int32_t(std::floor(f.x0 / f.cell)); i <= int32_t(std::floor(f.x1 / f.cell)); ++i) {
            TreeRecord tree;
            float t;
            if (!forestTreeAt(f, ForestGround{}, i, k, tree) || !intersectTree(tree, treeShapeOf(tree), ray, bvh.invDir, t)) continue;
            if (t < tHit) tHit = t;
            found = true;
        }
    return found;
}

/// Rays at a forest over [-150, 150)^2: from above, grazing among the trunks and crowns, and from
/// outside towards a point inside, in random directions.
Ray randomRay(HashStream& rng, int i) {
    Ray ray;
    const Vec3f target{rng.uniform(-150.0f, 150.0f), rng.uniform(0.0f, 12.0f), rng.uniform(-150.0f, 150.0f)};
    switch (i % 3) {
    case 0: ray.origin = {rng.uniform(-150.0f, 150.0f), rng.uniform(20.0f, 200.0f), rng.uniform(-150.0f, 150.0f)}; break;
    case 1: ray.origin = {rng.uniform(-150.0f, 150.0f), rng.uniform(0.5f, 14.0f), rng.uniform(-150.0f, 150.0f)}; break;
    default: ray.origin = {rng.uniform(-400.0f, 400.0f), rng.uniform(0.5f, 60.0f), rng.uniform(-400.0f, 400.0f)}; break;
    }
    ray.dir = i % 3 == 1 ? normalize(Vec3f{target.x - ray.origin.x, rng.uniform(-0.1f, 0.1f), target.z - ray.origin.z})
                         : normalize(target - ray.origin);
    return ray;
}

ForestRecord testForest(float cell, float density) {
    TreeOptions options;
    options.outerForestCell = cell;
    options.outerForestDensity = density;
    return forestRecordOf(-150.0f, -150.0f, 150.0f, 150.0f, options, 1, 1);
}

/// The walk against the brute force over `rays` random rays: no miss, no extra hit, the same distance.
void expectWalkFindsEveryTree(const ForestRecord& f, int rays) {
    HashStream rng{17};
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        const Ray ray = randomRay(rng, i);
        const BvhRay bvh(ray);
        float expected, t = 0, tAny = 0;
        int32_t cell[2];
        const bool reference = bruteForce(f, ray, expected);
        const bool walked = intersectForest(f, ForestGround{}, ray, bvh.invDir, false, t, cell);
        ASSERT_EQ(walked, reference) << "ray " << i << (reference ? ": a tree missed" : ": a tree where none is");
        EXPECT_EQ(intersectForest(f, ForestGround{}, ray, bvh.invDir, true, tAny, cell), reference) << "ray " << i << ", any hit";
        if (!reference) continue;
        ++hits;
        EXPECT_EQ(t, expected) << "ray " << i;
    }
    std::printf("cell %.1f m, %d neighbours: %d of %d rays hit a tree\n", double(f.cell), f.neighbours, hits, rays);
    EXPECT_GT(hits, rays / 3);
}

/// The share of a 96 x 54 grid of `camera`'s rays between `from` and `to` (shares of the image's
/// height from the top) that hit a forest tree.
double treeShare(const SceneView& view, const Camera& camera, float from, float to) {
    int trees = 0, rays = 0;
    for (int y = 0; y < 54; ++y)
        for (int x = 0; x < 96; ++x) {
            const float sy = (float(y) + 0.5f) / 54.0f;
            if (sy < from || sy > to) continue;
            ++rays;
            trees += traceScene(view, camera.generateRay((float(x) + 0.5f) / 96.0f, sy), false).kind == kPrimKindOf<ForestRecord>;
        }
    return double(trees) / double(rays);
}

} // namespace

TEST(Forest, CellWalkFindsEveryTreeABruteForceFinds) {
    expectWalkFindsEveryTree(testForest(6.0f, 250.0f), 900);
}

TEST(Forest, CellWalkFindsEveryTreeWhenCrownsReachSeveralCellsAway) {
    const ForestRecord f = testForest(2.5f, 600.0f);
    ASSERT_GE(f.neighbours, 3);
    expectWalkFindsEveryTree(f, 600);
}

TEST(Forest, EveryTreeFitsTheReachTheWalkAssumes) {
    for (const float variation : {0.0f, 0.25f, 0.9f}) {
        TreeOptions options;
        options.sizeVariation = variation;
        options.coniferShare = 0.5f;
        const ForestRecord f = forestRecordOf(-600.0f, -600.0f, 600.0f, 600.0f, options, 1, 1);
        float reach = 0, top = 0;
        for (int32_t k = -100; k < 100; ++k)
            for (int32_t i = -100; i < 100; ++i) {
                TreeRecord tree;
                if (!forestTreeAt(f, ForestGround{}, i, k, tree)) continue;
                const Bounds3f box = treeLocalBounds(treeShapeOf(tree));
                reach = std::max({reach, box.hi.x, box.hi.z, -box.lo.x, -box.lo.z});
                top = std::max(top, box.hi.y);
            }
        EXPECT_LE(reach, f.reach) << "variation " << variation;
        EXPECT_LE(top, f.top) << "variation " << variation;
        EXPECT_GT(reach, 0.9f * f.reach) << "the reach is not much larger than the largest tree's";
    }
}

TEST(Forest, MemoryDoesNotGrowWithItsArea) {
    const TreeOptions options;
    const ForestRecord small = forestRecordOf(-1000.0f, -1000.0f, 1000.0f, 1000.0f, options, 1, 1);
    const ForestRecord large = forestRecordOf(-10000.0f, -10000.0f, 10000.0f, 10000.0f, options, 1, 1);
    const uint64_t smallTrees = forestTreeCount(small), largeTrees = forestTreeCount(large);
    const Scene a = test::forestScene(small), b = test::forestScene(large);
    std::printf("forest of %llu trees: %zu bytes; of %llu trees: %zu bytes\n", (unsigned long long)smallTrees,
                a.memory().total(), (unsigned long long)largeTrees, b.memory().total());
    EXPECT_NEAR(double(largeTrees) / double(smallTrees), 100.0, 1.0);
    EXPECT_NEAR(double(largeTrees), 4e8 * options.outerForestDensity / 1e4, 0.01 * 4e8 * options.outerForestDensity / 1e4);
    EXPECT_EQ(a.memory().total(), b.memory().total());
    EXPECT_EQ(a.memory().forests, sizeof(ForestRecord));
}

TEST(Forest, RunsToTheHorizonAndCoversTheGroundFromAbove) {
    const Scene scene = test::forestScene(forestRecordOf(-20000.0f, -20000.0f, 20000.0f, 20000.0f, TreeOptions{}, 1, 1));
    const SceneView view = scene.view();
    // At street level, looking level: the forest closes the horizon (the image's middle): every ray
    // from it up to a tenth of the image's height above meets a tree, none the sky. (Below it, the
    // ground shows between the trunks, under the broadleaves' crowns.)
    const Camera street = makeLookAtCamera({3.0f, 1.7f, 2.0f}, {3.0f, 1.7f, -100.0f}, 50.0f, 16.0f / 9.0f);
    const double streetShare = treeShare(view, street, 0.4f, 0.5f);
    // From 300 m, looking straight down: crowns over most of the ground, the ground between them.
    const Camera above = makeLookAtCamera({0.0f, 300.0f, 0.0f}, {0.0f, 0.0f, -0.01f}, 50.0f, 16.0f / 9.0f);
    const double aboveShare = treeShare(view, above, 0.0f, 1.0f);
    std::printf("trees: %.3f of the rays just above the horizon at street level, %.3f of the view down from 300 m\n",
                streetShare, aboveShare);
    EXPECT_EQ(streetShare, 1.0);
    EXPECT_GT(aboveShare, 0.5);
    EXPECT_LT(aboveShare, 0.98);
}
