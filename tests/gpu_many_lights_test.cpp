// The light BVH and the colliders sampler on the GPU: the many-lights plane (tests/lights_test_scenes.h)
// path traced with each on both backends, and a wall of lit windows with the BVH and the power sampler. The GPU's shading math is the hardware's approximations
// (docs/architecture.md § Precision policy), so node importances, and with them some picks, differ
// in the last bits and send some paths elsewhere; pixels are not compared one by one. Tolerances: the
// image means within 1 % and each of 4 x 4 block means within 5 %, the margins the CPU's own
// samplers keep against each other at these counts (tests/integrator_many_lights_test.cpp).
#include "gpu_test_support.h"

#include "cpu/cpu_renderer.h"
#include "lights_test_scenes.h"
#include "night_test_scenes.h"
#include "scene/camera.h"
#include "scene/camera_framing.h"

#include <cmath>
#include <initializer_list>

using namespace urbis;

namespace {

std::vector<double> blockMeans(const LinearImage& image, uint32_t side, uint32_t blocks) {
    std::vector<double> means(blocks * blocks, 0.0);
    const uint32_t b = side / blocks;
    for (uint32_t y = 0; y < side; ++y)
        for (uint32_t x = 0; x < side; ++x) means[(y / b) * blocks + x / b] += luminance(image.pixels[y * side + x]) / (b * b);
    return means;
}

/// Renders `scene` with each sampler of `kinds` on both backends: the GPU's image mean within
/// `meanTolerance` of the CPU's, and each 4 x 4 block mean above `litShare` of the image's within
/// `blockTolerance` (a block darker than that is too noisy to compare).
void expectBackendsAgree(const Scene& scene, const Camera& camera, RenderSettings settings,
                         std::initializer_list<LightSamplerKind> kinds, double meanTolerance, double blockTolerance,
                         double litShare) {
    const std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const uint32_t side = settings.width;
    for (LightSamplerKind kind : kinds) {
        settings.lightSampler = kind;
        RenderCounters cpuCounters, gpuCounters;
        const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
        const LinearImage img = gpu->render(camera, settings, gpuCounters);
        ASSERT_EQ(img.pixels.size(), cpu.pixels.size());
        const std::vector<double> a = blockMeans(cpu, side, 1), b = blockMeans(img, side, 1);
        ASSERT_GT(a[0], 1e-3) << "the image is black";
        EXPECT_NEAR(b[0] / a[0], 1.0, meanTolerance) << "sampler " << int(kind);
        const std::vector<double> ca = blockMeans(cpu, side, 4), cb = blockMeans(img, side, 4);
        for (size_t i = 0; i < ca.size(); ++i) {
            if (ca[i] > litShare * a[0]) {
                EXPECT_NEAR(cb[i] / ca[i], 1.0, blockTolerance) << "sampler " << int(kind) << ", block " << i;
            }
        }
    }
}

} // namespace

TEST(GpuManyLights, BvhAndCollidersMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    Scene scene = test::manyEmitterScene(5000, 1000.0f);
    buildLights(scene);
    RenderSettings settings;
    settings.width = settings.height = 64;
    settings.spp = 256;
    const Camera camera = makeLookAtCamera(Vec3f{0, 40, 60}, Vec3f{0, 0, 0}, 60.0f, 1.0f);
    expectBackendsAgree(scene, camera, settings, {LightSamplerKind::Bvh, LightSamplerKind::Colliders}, 0.01, 0.05, 0.0);
}

// A wall of lit windows (one Aggregate light, 40 % of its rooms lit) over a plane at night, with the
// light BVH and the power sampler on both backends: the pick of a lit cell, the point on its glass
// and the MIS through the pane are the same code on both. The windows' light is noisier than the
// plane's above (a few bright panes): the image means within 2 % and each of 4 x 4 block means that
// is lit at all within 10 % (the CPU's MIS and BSDF-only images keep 10 % at 1024 spp:
// NightWindows.MisConvergesToBsdfSampling).
TEST(GpuManyLights, LitWindowsMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    TriangleMesh mesh;
    test::addSquare(mesh, 200.0f, 0.0f, 0);
    Scene scene = test::nightScene(mesh, test::wallMaterials(), {test::testWall(6, 4, 0.4f, 99u)}, {});
    buildLights(scene);
    ASSERT_NE(scene.lights.first<WindowLight>(), kNoLight);
    RenderSettings settings;
    settings.width = settings.height = 64;
    settings.spp = 512;
    const Camera camera = cameraFromHeading(Vec3f{0.0f, 1.7f, 14.0f}, 0.0f, -20.0f, 60.0f, 1.0f);
    expectBackendsAgree(scene, camera, settings, {LightSamplerKind::Bvh, LightSamplerKind::Power}, 0.02, 0.10, 1e-3);
}
