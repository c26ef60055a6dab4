// The kinds and features a scene holds (scene/scene_features.h) and the GPU render kernel that runs
// it (gpu/render_variants.h): every set of features has a kernel that holds them all and takes the
// scene's own traversal; scenes pick the kernels meant for them; and per-ray code given the kernel's
// set instead of the scene's own computes the same bits (what the kernel's constants must not change).
#include "tree_test_scenes.h"

#include "gpu/render_variants.h"
#include "integrators/integrator.h"
#include "media/cloud_build.h"
#include "nature/forest_records.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace urbis;

TEST(SceneFeatures, EverySetHasAKernelThatHoldsItWithTheScenesTraversal) {
    for (SceneFeatures features = 0; features <= kAllFeatures; ++features) {
        const uint32_t variant = renderVariantFor(features);
        ASSERT_LT(variant, kRenderVariantCount);
        EXPECT_TRUE(hasFeatures(kRenderVariants[variant], features)) << features;
        // The kernel fixes SceneView::costlyLeaves: it must be the scene's (any costly kind held).
        EXPECT_EQ(renderVariantHasCostlyLeaves(kRenderVariants[variant]), (features & kCostlyKindFeatures) != 0) << features;
    }
    EXPECT_EQ(kRenderVariants[kRenderVariantCount - 1], kAllFeatures);
}

TEST(SceneFeatures, ScenesPickTheKernelsMeantForThem) {
    const Scene grove = test::groveScene(3, false), twin = test::groveScene(3, true);
    EXPECT_EQ(grove.view().features, kKindFeature<TreeRecord> | kKindFeature<GroundRecord>);
    EXPECT_EQ(kRenderVariants[renderVariantFor(grove.view().features)],
              kCityFeatures | kKindFeature<TreeRecord> | kKindFeature<ForestRecord>);
    const Scene forest = test::forestScene(forestRecordOf(-100.0f, -100.0f, 100.0f, 100.0f, TreeOptions{}, 1, 1));
    EXPECT_EQ(forest.view().features, kKindFeature<ForestRecord> | kKindFeature<GroundRecord>);
    EXPECT_EQ(renderVariantFor(forest.view().features), renderVariantFor(grove.view().features));
    EXPECT_EQ(twin.view().features, kKindFeature<Triangle> | kKindFeature<GroundRecord>);
    EXPECT_EQ(kRenderVariants[renderVariantFor(twin.view().features)], kTriangleCityFeatures);
    Scene cloudy = test::groveScene(3, false);
    CloudLayer layer;
    layer.type = CloudType::Uniform;   // no noise volume to build
    layer.coverage = 0.5f;
    buildClouds(cloudy, layer);
    EXPECT_TRUE(hasFeatures(cloudy.view().features, kCloudsFeature));
    EXPECT_EQ(kRenderVariants[renderVariantFor(cloudy.view().features)], kAllFeatures);
    layer.coverage = 0.0f;   // no layer is kept: no clouds to track
    buildClouds(cloudy, layer);
    EXPECT_FALSE(hasFeatures(cloudy.view().features, kCloudsFeature));
}

TEST(SceneFeatures, TheKernelsSetRendersTheSameBitsAsTheScenesOwn) {
    const Scene scene = test::groveScene(3, false);
    const SceneView own = scene.view();
    SceneView kernels = own;
    kernels.features = kRenderVariants[renderVariantFor(own.features)];
    ASSERT_NE(kernels.features, own.features);
    SceneView everything = own;
    everything.features = kAllFeatures;
    RenderSettings settings;
    settings.width = 24;
    settings.height = 16;
    const Camera camera = makeLookAtCamera({0, 6, 30}, {0, 4, 0}, 50.0f, 1.5f);
    uint32_t differing = 0, rays = 0;
    for (uint32_t y = 0; y < settings.height; ++y)
        for (uint32_t x = 0; x < settings.width; ++x)
            for (uint32_t s = 0; s < 2; ++s) {
                const PathSample a = integrateSample(own, camera, settings, x, y, s);
                const PathSample b = integrateSample(kernels, camera, settings, x, y, s);
                const PathSample c = integrateSample(everything, camera, settings, x, y, s);
                differing += std::memcmp(&a.radiance, &b.radiance, sizeof(Vec3f)) != 0 ||
                             std::memcmp(&a.radiance, &c.radiance, sizeof(Vec3f)) != 0 || a.rays != b.rays;
                rays += a.rays;
            }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(rays, settings.width * settings.height * 2);   // paths went on past the camera ray
}
