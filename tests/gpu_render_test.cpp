// Image parity: the same scene, camera and seed path traced on the GPU and on the CPU.
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "lights/light_build.h"
#include "media/atmosphere_build.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"

#include <algorithm>
#include <cmath>

using namespace urbis;

// Metric: per-pixel luminance of the linear images (mean of spp samples). Both backends run the
// same tracePath on the same sample streams, so pixels differ only where rounding sends one
// sample's path elsewhere: the GPU's shading math is the hardware's approximations
// (the precision policy, docs/architecture.md), its hits exact. Tolerances: the mean
// absolute difference under 0.1% of the mean luminance, at most 1% of pixels off by more than
// 0.1% relative, and no pixel off by more than the largest single-sample change spread over spp
// (bounded here by 2 x mean luminance x 64 / spp).
namespace {

/// Renders the Bavarian village in `geometry` ("procedural": walls in the BVH, the GPU's mixed-layout
/// render kernel; "plain": stored triangles only, its triangle-layout kernel) on both backends and
/// checks the tolerances above. With `atmosphere`, under Hillaire's atmosphere (its tables, aerial
/// perspective on every segment) with the light list built (the sky's table from its radiance).
void expectVillageImagesMatch(const std::string& geometry, bool atmosphere = false) {
    CityModel city = importOsm(test::villageFile(), ImportOptions{});
    CityMeshOptions options;
    options.geometry = parseGeometryModes(geometry);
    CityMesh mesh = meshCity(city, options);
    Scene scene = buildCityScene(mesh);
    ASSERT_EQ(!scene.walls.empty(), geometry == "procedural");
    scene.sun = makeSun(35.0f, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    if (atmosphere) {
        scene.sky.model = SkyModel::Atmosphere;
        buildAtmosphere(scene);
        buildLights(scene);
    }
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 7;
    Camera camera = frameCity(mesh.cityBounds, 50.0f, float(settings.width) / float(settings.height));

    RenderCounters cpuCounters, gpuCounters;
    LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    LinearImage img = gpu->render(camera, settings, gpuCounters);
    ASSERT_EQ(img.pixels.size(), cpu.pixels.size());

    double sum = 0, sumDiff = 0, worst = 0;
    size_t off = 0, identical = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) {
        double a = luminance(cpu.pixels[i]), b = luminance(img.pixels[i]);
        ASSERT_TRUE(std::isfinite(b)) << "pixel " << i;
        sum += a;
        sumDiff += std::fabs(a - b);
        worst = std::max(worst, std::fabs(a - b));
        off += std::fabs(a - b) > 1e-3 * std::max(a, 1e-6);
        identical += cpu.pixels[i].x == img.pixels[i].x && cpu.pixels[i].y == img.pixels[i].y &&
                     cpu.pixels[i].z == img.pixels[i].z;
    }
    const double n = double(cpu.pixels.size()), mean = sum / n;
    std::printf("image parity (%s%s): mean luminance %.5f, mean |diff| %.3g (%.4f%%), worst %.4g, %zu of %zu pixels "
                "off by > 0.1%%, %zu bit-identical; rays cpu %llu gpu %llu\n",
                geometry.c_str(), atmosphere ? ", atmosphere" : "", mean, sumDiff / n, 100.0 * sumDiff / n / mean, worst, off, cpu.pixels.size(),
                identical, (unsigned long long)cpuCounters.rays, (unsigned long long)gpuCounters.rays);
    ASSERT_GT(mean, 0.01) << "the image is black";
    EXPECT_LT(sumDiff / n, 1e-3 * mean);
    EXPECT_LE(double(off), 0.01 * n);
    EXPECT_LE(worst, 2.0 * mean * 64.0 / settings.spp);
    // Ray counts differ only by the paths that rounding sends elsewhere.
    EXPECT_NEAR(double(gpuCounters.rays), double(cpuCounters.rays), 1e-3 * double(cpuCounters.rays));
}

} // namespace

TEST(GpuRender, VillageWithProceduralFacadesMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    expectVillageImagesMatch("procedural");
}

TEST(GpuRender, VillageOfStoredTrianglesMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    expectVillageImagesMatch("plain");
}

TEST(GpuRender, VillageUnderTheAtmosphereMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    expectVillageImagesMatch("procedural", true);
}
