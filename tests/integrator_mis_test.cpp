// MIS, light sampling and BSDF sampling converge to the same known radiance on analytic scenes:
// a Lambertian plane under a uniform sky (rho L), and a plane under an emitting square (rho L F,
// with F the point-to-square form factor). Every strategy's image mean must fall within the stated
// tolerance of the analytic value; each tolerance is more than 4 standard errors of its estimate.
#include "cpu/cpu_renderer.h"
#include "integrators/integrator.h"
#include "lights_test_scenes.h"
#include "scene/camera_framing.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

struct Strategy {
    const char* name;
    uint32_t lightSamples;
    LightSamplerKind sampler;
    bool buildTables;
    bool compensateSky = true;
};

const Strategy kStrategies[] = {
    {"BSDF sampling alone", 0, LightSamplerKind::Power, true},
    {"MIS, power sampler", 1, LightSamplerKind::Power, true},
    {"MIS, uniform sampler", 1, LightSamplerKind::Uniform, true},
    {"MIS, light BVH", 1, LightSamplerKind::Bvh, true},
    {"MIS, colliders", 1, LightSamplerKind::Colliders, true},
    {"MIS, 3 light samples", 3, LightSamplerKind::Power, true},
    {"MIS, sky table not compensated", 1, LightSamplerKind::Power, true, false},
    {"lights not built (the sun alone is light-sampled)", 1, LightSamplerKind::Power, false},
};

Vec3f imageMean(const LinearImage& image) {
    Vec3f sum;
    for (const Vec3f& p : image.pixels) sum += p;
    return sum / float(image.pixels.size());
}

Vec3f renderMean(Scene scene, const Strategy& strategy, const Camera& camera, uint32_t side, uint32_t spp) {
    LightBuildOptions options;
    options.compensateSky = strategy.compensateSky;
    if (strategy.buildTables) buildLights(scene, options);
    RenderSettings settings;
    settings.width = settings.height = side;
    settings.spp = spp;
    settings.lightSamples = strategy.lightSamples;
    settings.lightSampler = strategy.sampler;
    RenderCounters counters;
    return imageMean(renderCpu(scene.view(), camera, settings, false, counters));
}

void expectNear(Vec3f got, Vec3f expected, float tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c] / expected[c], 1.0f, tolerance) << what << ", channel " << c;
}

/// Point-to-rectangle form factor for a point under a corner of a parallel a x b rectangle at height h
/// (Howell's catalogue, configuration B-3).
double cornerFormFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
            y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) / (2 * M_PI);
}

} // namespace

TEST(IntegratorMis, PlaneUnderUniformSky) {
    const Vec3f albedo{0.8f, 0.5f, 0.25f}, sky{1.0f, 2.0f, 0.5f};
    TriangleMesh mesh;
    test::addSquare(mesh, 400.0f, 0.0f, 0);
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{albedo}}});
    scene.sky = Sky::uniform(sky);
    const Camera camera = cameraFromHeading(Vec3f{0, 10, 0}, 30.0f, -60.0f, 40.0f, 1.0f);
    for (const Strategy& s : kStrategies) expectNear(renderMean(scene, s, camera, 24, 96), albedo * sky, 0.005f, s.name);
}

// Radiance of a Lambertian plane straight under the centre of a square of side 2 h at height h,
// emitting L downwards (and upwards, where nothing is), with a black sky: rho L F.
TEST(IntegratorMis, PlaneUnderEmittingSquare) {
    const float h = 1.0f;
    const Vec3f albedo{0.5f, 0.6f, 0.7f}, radiance{5.0f, 4.0f, 3.0f};
    TriangleMesh mesh;
    test::addSquare(mesh, 400.0f, 0.0f, 0);
    test::addSquare(mesh, 2.0f * h, h, 1);
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{albedo}, test::emitter(radiance)}});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    const float formFactor = float(4.0 * cornerFormFactor(h, h, h));
    // A narrow view of the plane's centre, where F changes by less than 1e-4.
    const Camera camera = makeLookAtCamera(Vec3f{0, 0.5f * h, 0}, Vec3f{0, 0, 0}, 1.0f, 1.0f);
    for (const Strategy& s : kStrategies)
        expectNear(renderMean(scene, s, camera, 32, 256), albedo * radiance * formFactor, 0.01f, s.name);
}
