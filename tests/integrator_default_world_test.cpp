// The default world (the generated city of `urbis render`) rendered with MIS over every light
// against a reference that light-samples the sun alone and finds the sky and every emitter by
// BSDF sampling, counting them in full (the estimator the path tracer had before MIS): MIS
// changes the noise, not the mean. Tolerances: the image mean within 1 %, and each of 6 x 6
// blocks within 5 % (measured: 0.05 % and 1.5 % at 96 x 54 pixels, 128 spp).
#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "layout/city_layout.h"
#include "lights/light_build.h"
#include "scene/camera_framing.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

struct World {
    Scene scene;
    Camera camera;
};

World defaultWorld(float aspect) {
    const CityModel city = generateCity(LayoutParams{});
    CityMesh mesh = meshCity(city, CityMeshOptions{});
    World w{buildCityScene(mesh),
            frameCity(mesh.framingPieces, 50.0f, aspect)};
    w.scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    return w;
}

/// Luminance means of the whole image and of `blocks` x `blocks` blocks.
std::vector<double> blockMeans(const LinearImage& image, uint32_t blocks) {
    std::vector<double> sums(blocks * blocks + 1, 0.0), counts(blocks * blocks + 1, 0.0);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const double l = luminance(image.pixels[size_t(y) * image.width + x]);
            const uint32_t b = (y * blocks / image.height) * blocks + x * blocks / image.width;
            sums[b] += l;
            counts[b] += 1;
            sums.back() += l;
            counts.back() += 1;
        }
    for (size_t i = 0; i < sums.size(); ++i) sums[i] /= counts[i];
    return sums;
}

} // namespace

TEST(IntegratorDefaultWorld, MisKeepsTheMean) {
    RenderSettings settings;
    settings.width = 96;
    settings.height = 54;
    settings.spp = 128;
    World world = defaultWorld(float(settings.width) / float(settings.height));
    RenderCounters counters;
    LightBuildOptions sunOnly;
    sunOnly.sky = sunOnly.surfaces = false;
    buildLights(world.scene, sunOnly);
    const std::vector<double> reference = blockMeans(renderCpu(world.scene.view(), world.camera, settings, false, counters), 6);
    // The sun outshines the sky's table here, so the default list leaves the sky to BSDF sampling
    // (light_build.cpp); MIS over every light is what this test checks.
    buildLights(world.scene);
    EXPECT_EQ(world.scene.lights.first<SkyLight>(), kNoLight);
    LightBuildOptions everyLight;
    everyLight.skyMinShare = 0.0f;
    buildLights(world.scene, everyLight);
    EXPECT_NE(world.scene.lights.first<SkyLight>(), kNoLight);
    const std::vector<double> mis = blockMeans(renderCpu(world.scene.view(), world.camera, settings, false, counters), 6);
    EXPECT_NEAR(mis.back() / reference.back(), 1.0, 0.01) << "image mean";
    double worst = 0;
    for (size_t b = 0; b + 1 < mis.size(); ++b) worst = std::max(worst, std::fabs(mis[b] / reference[b] - 1.0));
    EXPECT_LT(worst, 0.05) << "largest relative difference of a block's mean";
    std::printf("default world: image mean MIS / reference - 1 = %+.4f, worst block %.4f\n", mis.back() / reference.back() - 1.0, worst);
}
