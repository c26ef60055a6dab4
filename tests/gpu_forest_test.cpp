// The forest by domain repetition on both backends: rays at a forest hit the same tree at the same
// distance, bit for bit (its cells, trees and sphere traces use urbis.h's exact operations), and a
// forest to the horizon path traced on the GPU matches the CPU's image.
#include "gpu_test_support.h"

#include "nature/forest_records.h"
#include "tree_test_scenes.h"

using namespace urbis;

TEST(GpuForest, RaysAtAForestHitTheSameTreeAtTheSameDistance) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::forestScene(forestRecordOf(-300.0f, -300.0f, 300.0f, 300.0f, TreeOptions{}, 1, 1));
    const std::vector<Ray> rays = test::raysBetweenBoxes({-500.0f, 0.5f, -500.0f}, {500.0f, 200.0f, 500.0f},
                                                         {-300.0f, 0.0f, -300.0f}, {300.0f, 12.0f, 300.0f}, 200000, 78u);
    test::expectSameHits(scene, rays, kPrimKindOf<ForestRecord>, "forest", 0.5);
}

// Metric: per-pixel luminance of the linear images, as the trees' city image (gpu_trees_test.cpp):
// the mean absolute difference under 0.1 % of the mean, at most 1 % of pixels off by more than 0.1 %.
TEST(GpuForest, ForestToTheHorizonMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::forestScene(forestRecordOf(-20000.0f, -20000.0f, 20000.0f, 20000.0f, TreeOptions{}, 1, 1));
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 7;
    const Camera camera = makeLookAtCamera({0.0f, 30.0f, 0.0f}, {0.0f, 0.0f, -60.0f}, 50.0f,
                                           float(settings.width) / float(settings.height));
    LinearImage cpu, gpu;
    test::expectParity(test::renderOnBoth(scene, camera, settings, "forest", cpu, gpu), 1e-3, 0.01);
}
