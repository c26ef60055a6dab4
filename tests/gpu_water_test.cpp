// Water on the GPU: a pond with waves, its bed falling from the shore, seen from above at an angle
// under a low sun, path traced on both backends. The waves' normals, the Fresnel split and the
// absorption run on the GPU's approximate math (the precision policy, docs/architecture.md), so a
// few paths turn the other way at a reflection: the images agree on average, not bit for bit.
#include "gpu_test_support.h"
#include "water_scenes.h"

#include "scene/camera_framing.h"

using namespace urbis;

// Metric: the mean absolute difference of per-pixel luminance under 3 % of the mean luminance, and
// the mean luminance of the water alone within 2 % (64 spp). Both backends draw the same samples, so
// the difference is only the paths that the approximate math turns the other way; the tolerances are
// set from the night sky's (1 %) with room for the waves' sun glints, not yet measured on a GPU.
TEST(GpuWater, PondMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::waterScene({test::squareArea(AreaKind::Park, 200), test::squareArea(AreaKind::Water, 40)},
                                         20.0f, 200.0f);
    constexpr uint32_t kWidth = 96;
    LinearImage cpu, gpu;
    test::expectParity(test::renderOnBoth(scene, cameraFromHeading({0, 30, 70}, 0.0f, -35.0f, 50.0f, 1.5f), kWidth, 64, 64,
                                          "water", cpu, gpu),
                       0.03);
    ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
    // The pond fills the middle rows of the frame: compare their mean.
    double cpuWater = 0, gpuWater = 0;
    for (uint32_t y = 28; y < 40; ++y)
        for (uint32_t x = 32; x < 64; ++x) {
            cpuWater += luminance(cpu.pixels[y * kWidth + x]);
            gpuWater += luminance(gpu.pixels[y * kWidth + x]);
        }
    EXPECT_NEAR(gpuWater / cpuWater, 1.0, 0.02);
}
