// Water on the GPU: a pond with waves, its bed falling from the shore, seen from above at an angle
// under a low sun, path traced on both backends. The waves' normals, the Fresnel split and the
// absorption run on the GPU's approximate math (the precision policy, docs/architecture.md), so a
// few paths turn the other way at a reflection: the images agree on average, not bit for bit.
#include "gpu_test_support.h"

#include "cpu/cpu_renderer.h"
#include "lights/light_build.h"
#include "scene/camera_framing.h"
#include "streets/ground_cover.h"
#include "streets/street_materials.h"

#include <cmath>
#include <cstdio>

using namespace urbis;

namespace {

Area squareArea(AreaKind kind, double half) {
    Area a;
    a.kind = kind;
    a.polygon.outer = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    return a;
}

} // namespace

// Metric: the mean absolute difference of per-pixel luminance under 3 % of the mean luminance, and
// the mean luminance of the water alone within 2 % (both 64 spp; the CPU's own noise between two
// seeds is about 1.5 % there).
TEST(GpuWater, PondMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    CityModel city;
    city.areas = {squareArea(AreaKind::Park, 200), squareArea(AreaKind::Water, 40)};
    StreetMesh out;
    meshGroundCover(city, {}, out);
    Scene scene = Scene::build(out.mesh, streetMaterials(), {}, {},
                               {GroundRecord::around(0, 0, 0, uint32_t(StreetMaterial::Grass))});
    scene.sun = makeSun(20.0f, 200.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    buildLights(scene);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.spp = 64;
    const Camera camera = cameraFromHeading({0, 30, 70}, 0.0f, -35.0f, 50.0f, 1.5f);
    RenderCounters cpuCounters, gpuCounters;
    const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    const LinearImage gpu = GpuScene::upload(scene)->render(camera, settings, gpuCounters);
    ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
    double sum = 0, sumDiff = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(gpu.pixels[i]);
        ASSERT_TRUE(std::isfinite(b)) << "pixel " << i;
        sum += a;
        sumDiff += std::fabs(a - b);
    }
    std::printf("water parity: mean luminance %.4g, mean |diff| %.3g\n", sum / double(cpu.pixels.size()),
                sumDiff / double(cpu.pixels.size()));
    ASSERT_GT(sum, 0.0);
    EXPECT_LT(sumDiff, 0.03 * sum);
    // The pond fills the middle rows of the frame: compare their mean.
    double cpuWater = 0, gpuWater = 0;
    for (uint32_t y = 28; y < 40; ++y)
        for (uint32_t x = 32; x < 64; ++x) {
            cpuWater += luminance(cpu.pixels[y * settings.width + x]);
            gpuWater += luminance(gpu.pixels[y * settings.width + x]);
        }
    EXPECT_NEAR(gpuWater / cpuWater, 1.0, 0.02);
}
