// Clouds on the GPU against the CPU: the Bavarian village under cumulus and Hillaire's atmosphere,
// seen from above (the clouds' shadows on the village) and from the street looking up (the clouds,
// lit by the sun and the sky, and the sky through their gaps).
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "lights/light_build.h"
#include "media/atmosphere_build.h"
#include "media/cloud_build.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"

#include <cmath>

using namespace urbis;

// Metric: per-pixel luminance of the linear images. Both backends walk the same tracking on the same
// sample streams, but every tracking step compares a random number with a density that the GPU's
// approximate arithmetic (the precision policy, docs/architecture.md) rounds differently, so more
// paths part ways than without clouds and then differ as independent samples do (on the H200 the
// mean absolute pixel difference was 10-12 % of the mean at 64 spp, the means within 0.05 %).
// Tolerances: the images' mean luminance within 1 %; the mean absolute pixel difference at most
// 1.15 times that between two CPU renders of independent seeds (the GPU may part ways from the CPU
// no more than an independent render does).
namespace {

void expectCloudImagesMatch(bool fromStreet) {
    CityModel city = importOsm(test::villageFile(), ImportOptions{});
    CityMesh mesh = meshCity(city, CityMeshOptions{});
    Scene scene = buildCityScene(mesh);
    scene.sun = makeSun(35.0f, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    scene.sky.model = SkyModel::Atmosphere;
    buildAtmosphere(scene);
    CloudLayer clouds;
    clouds.coverage = 0.6f;
    buildClouds(scene, clouds);
    buildLights(scene);
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 11;
    const float aspect = float(settings.width) / float(settings.height);
    const Vec3f centre = mesh.cityBounds.centre();
    const Camera camera = fromStreet ? cameraFromHeading(Vec3f{centre.x, 2.0f, centre.z}, 140.0f, 35.0f, 70.0f, aspect)
                                     : frameCity(mesh.cityBounds, 50.0f, aspect);
    RenderCounters cpuCounters, gpuCounters;
    const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const LinearImage img = gpu->render(camera, settings, gpuCounters);
    RenderSettings otherSeed = settings;
    otherSeed.seed = settings.seed + 1;
    const LinearImage independent = renderCpu(scene.view(), camera, otherSeed, false, cpuCounters);
    ASSERT_EQ(img.pixels.size(), cpu.pixels.size());
    double sumCpu = 0, sumGpu = 0, sumDiff = 0, sumNoise = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(img.pixels[i]);
        ASSERT_TRUE(std::isfinite(b)) << "pixel " << i;
        sumCpu += a;
        sumGpu += b;
        sumDiff += std::fabs(a - b);
        sumNoise += std::fabs(a - double(luminance(independent.pixels[i])));
    }
    const double n = double(cpu.pixels.size()), mean = sumCpu / n;
    std::printf("clouds parity (%s): mean luminance cpu %.5f gpu %.5f, mean |diff| %.3g (%.2f%%), between CPU seeds %.3g\n",
                fromStreet ? "street" : "above", mean, sumGpu / n, sumDiff / n, 100.0 * sumDiff / n / mean, sumNoise / n);
    ASSERT_GT(mean, 0.01) << "the image is black";
    EXPECT_NEAR(sumGpu / n, mean, 0.01 * mean);
    EXPECT_LT(sumDiff, 1.15 * sumNoise);
}

} // namespace

TEST(GpuClouds, VillageUnderCumulusFromAboveMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectCloudImagesMatch(false);
}

TEST(GpuClouds, CumulusSeenFromTheStreetMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectCloudImagesMatch(true);
}
