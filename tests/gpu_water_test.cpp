// Water on the GPU: a pond with waves, its bed falling from the shore, seen from above at an angle
// under a low sun, path traced on both backends. The waves' normals, the Fresnel split and the
// absorption run on the GPU's approximate math (the precision policy, docs/architecture.md), so a
// few paths turn the other way at a reflection: the images agree on average, not bit for bit.
#include "gpu_test_support.h"
#include "water_scenes.h"

#include "cpu/cpu_renderer.h"
#include "scene/camera_framing.h"

#include <cstdio>

using namespace urbis;

// Metric: the mean absolute difference of per-pixel luminance under 3 % of the mean luminance, and
// the mean luminance of the water alone within 2 % (both 64 spp; the CPU's own noise between two
// seeds is about 1.5 % there).
TEST(GpuWater, PondMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::waterScene({test::squareArea(AreaKind::Park, 200), test::squareArea(AreaKind::Water, 40)},
                                         20.0f, 200.0f);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.spp = 64;
    const Camera camera = cameraFromHeading({0, 30, 70}, 0.0f, -35.0f, 50.0f, 1.5f);
    RenderCounters cpuCounters, gpuCounters;
    const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    const LinearImage gpu = GpuScene::upload(scene)->render(camera, settings, gpuCounters);
    ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
    const test::LuminanceParity parity = test::luminanceParity(cpu, gpu);
    std::printf("water parity: mean luminance %.4g, mean |diff| %.3g\n", parity.mean, parity.meanDiff);
    ASSERT_TRUE(parity.finite);
    ASSERT_GT(parity.mean, 0.0);
    EXPECT_LT(parity.meanDiff, 0.03 * parity.mean);
    // The pond fills the middle rows of the frame: compare their mean.
    double cpuWater = 0, gpuWater = 0;
    for (uint32_t y = 28; y < 40; ++y)
        for (uint32_t x = 32; x < 64; ++x) {
            cpuWater += luminance(cpu.pixels[y * settings.width + x]);
            gpuWater += luminance(gpu.pixels[y * settings.width + x]);
        }
    EXPECT_NEAR(gpuWater / cpuWater, 1.0, 0.02);
}
