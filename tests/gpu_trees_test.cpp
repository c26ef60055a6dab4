// Trees on both backends: rays aimed at a grove hit the same tree at the same distance, bit for bit
// (the sphere tracer and the distance function use urbis.h's exact operations), and the path-traced
// generated city with its trees matches the CPU's image within gpu_render_test's tolerances.
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "geometry/scene_intersect.h"
#include "layout/city_layout.h"
#include "math/hash.h"
#include "scene/camera_framing.h"
#include "tree_test_scenes.h"

#include <cmath>

using namespace urbis;

TEST(GpuTrees, RaysAtAGroveHitTheSameTreeAtTheSameDistance) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::groveScene(6, false);
    std::vector<Ray> rays;
    HashStream rng{77u};
    for (int i = 0; i < 200000; ++i) {
        const Vec3f target{rng.uniform(-28.0f, 28.0f), rng.uniform(0.0f, 12.0f), rng.uniform(-28.0f, 28.0f)};
        const Vec3f origin{rng.uniform(-60.0f, 60.0f), rng.uniform(0.5f, 40.0f), rng.uniform(-60.0f, 60.0f)};
        rays.push_back(Ray{origin, target - origin});
    }
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const std::vector<SurfaceHit> gpuHits = gpu->intersect(rays);
    const std::vector<uint8_t> gpuBlocked = gpu->occluded(rays);
    const SceneView view = scene.view();
    size_t treeHits = 0, differ = 0, blockDiffer = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const SurfaceHit c = intersectScene(view, rays[i]);
        const SurfaceHit& g = gpuHits[i];
        treeHits += c.kind == kPrimKindOf<TreeRecord>;
        differ += c.kind != g.kind || c.index != g.index || c.t != g.t;
        blockDiffer += uint8_t(occludedScene(view, rays[i])) != gpuBlocked[i];
    }
    std::printf("trees on both backends: %zu rays, %zu hit a tree, %zu differ, %zu occlusions differ\n", rays.size(),
                treeHits, differ, blockDiffer);
    EXPECT_GT(treeHits, rays.size() / 4);
    EXPECT_EQ(differ, 0u);
    EXPECT_EQ(blockDiffer, 0u);
}

TEST(GpuTrees, GeneratedCityWithTreesMatchesTheCpuAt64Spp) {
    URBIS_SKIP_WITHOUT_GPU();
    LayoutParams params;
    params.buildings = 200;
    CityModel city = generateCity(params);
    CityMesh mesh = meshCity(city);
    ASSERT_GT(mesh.trees.size(), 50u);
    Scene scene = buildCityScene(mesh);
    scene.sun = makeSun(35.0f, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 7;
    const Camera camera = frameCity(mesh.cityBounds, 50.0f, float(settings.width) / float(settings.height));
    RenderCounters cpuCounters, gpuCounters;
    const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const LinearImage img = gpu->render(camera, settings, gpuCounters);
    ASSERT_EQ(img.pixels.size(), cpu.pixels.size());
    double sum = 0, sumDiff = 0;
    size_t off = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(img.pixels[i]);
        ASSERT_TRUE(std::isfinite(b));
        sum += a;
        sumDiff += std::fabs(a - b);
        off += std::fabs(a - b) > 1e-3 * std::max(a, 1e-6);
    }
    const double n = double(cpu.pixels.size()), mean = sum / n;
    std::printf("city with trees: mean luminance %.5f, mean |diff| %.3g, %zu of %zu pixels off by > 0.1%%\n", mean,
                sumDiff / n, off, cpu.pixels.size());
    EXPECT_LT(sumDiff / n, 1e-3 * mean);
    EXPECT_LE(double(off), 0.01 * n);
}
