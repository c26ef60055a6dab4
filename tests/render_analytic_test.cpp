// The path tracer against analytic radiance: a Lambertian plane under a uniform sky and a sun.
#include "cpu/cpu_renderer.h"
#include "math/constants.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

/// A horizontal square of two triangles, 400 m wide; the cameras below see only its middle.
Scene planeScene(Vec3f albedo) {
    TriangleMesh mesh;
    float h = 200.0f;
    Vec3f a{-h, 0, -h}, b{h, 0, -h}, c{h, 0, h}, d{-h, 0, h};
    mesh.add({a, d, c}, {0, 0});
    mesh.add({a, c, b}, {0, 0});
    return Scene::build({.mesh = mesh, .materials = {Material{albedo}}});
}

/// Mean and largest relative deviation of every pixel's channel `c` from `expected`.
void expectImageNear(const LinearImage& image, Vec3f expected, float tolerance) {
    float worst = 0;
    for (const Vec3f& p : image.pixels)
        for (int c = 0; c < 3; ++c) worst = fmaxf(worst, fabsf(p[c] - expected[c]) / expected[c]);
    EXPECT_LT(worst, tolerance) << "largest relative pixel error";
}

RenderSettings smallSettings(uint32_t spp) {
    RenderSettings s;
    s.width = 32;
    s.height = 24;
    s.spp = spp;
    return s;
}

} // namespace

// Under a uniform sky of radiance L, a Lambertian plane of albedo rho reflects rho * L in every
// direction (the sky fills the hemisphere, nothing else is visible from the plane).
TEST(AnalyticRadiance, LambertianPlaneUnderUniformSky) {
    Vec3f albedo{0.8f, 0.5f, 0.25f};
    Vec3f sky{1.0f, 2.0f, 0.5f};
    Scene scene = planeScene(albedo);
    scene.sky = Sky::uniform(sky);
    Camera camera = cameraFromHeading(Vec3f{0, 10, 0}, 30.0f, -60.0f, 40.0f, 32.0f / 24.0f);
    RenderCounters counters;
    LinearImage image = renderCpu(scene.view(), camera, smallSettings(256), false, counters);
    expectImageNear(image, albedo * sky, 0.01f);
    EXPECT_GT(counters.rays, 32u * 24u * 256u);
}

// The analytic ground plane must give the same answer as the triangles.
TEST(AnalyticRadiance, GroundPlaneUnderUniformSky) {
    Vec3f albedo{0.3f, 0.6f, 0.9f};
    Vec3f sky{2.0f, 1.0f, 0.5f};
    Scene scene = Scene::build({.materials = {Material{albedo}},
                                .grounds = {GroundRecord::around(0.0f, 0.0f, -3.0f, 0)}});
    scene.sky = Sky::uniform(sky);
    Camera camera = cameraFromHeading(Vec3f{1000, 40, -2000}, 10.0f, -30.0f, 40.0f, 32.0f / 24.0f);
    RenderCounters counters;
    LinearImage image = renderCpu(scene.view(), camera, smallSettings(64), false, counters);
    expectImageNear(image, albedo * sky, 0.01f);
}

// Adding a sun of irradiance E at elevation theta: rho * (L + E * <cos> / pi), where the disk's
// mean cosine over a uniform cone of half-angle r is sin(theta) * (1 + cos r) / 2.
TEST(AnalyticRadiance, LambertianPlaneUnderSkyAndSun) {
    Vec3f albedo{0.7f, 0.7f, 0.7f};
    Vec3f sky{0.3f, 0.4f, 0.6f};
    Vec3f irradiance{3.0f, 2.5f, 2.0f};
    float elevation = 35.0f, radius = 2.0f;
    Scene scene = planeScene(albedo);
    scene.sky = Sky::uniform(sky);
    scene.sun = makeSun(elevation, 120.0f, radius, irradiance);
    float meanCosine = std::sin(elevation * kPi / 180.0f) * 0.5f * (1.0f + std::cos(radius * kPi / 180.0f));
    Vec3f expected = albedo * (sky + irradiance * (meanCosine / kPi));
    Camera camera = cameraFromHeading(Vec3f{0, 10, 0}, 200.0f, -50.0f, 40.0f, 32.0f / 24.0f);
    RenderCounters counters;
    LinearImage image = renderCpu(scene.view(), camera, smallSettings(256), false, counters);
    expectImageNear(image, expected, 0.01f);
}

// A plane in full shadow of a roof receives no sun: the shadow ray must find the occluder.
TEST(AnalyticRadiance, ShadowedPlaneSeesNoSun) {
    Vec3f albedo{0.5f, 0.5f, 0.5f};
    TriangleMesh mesh;
    float h = 200.0f, r = 50.0f, top = 20.0f;
    mesh.add({{-h, 0, -h}, {-h, 0, h}, {h, 0, h}}, {0, 0});
    mesh.add({{-h, 0, -h}, {h, 0, h}, {h, 0, -h}}, {0, 0});
    mesh.add({{-r, top, -r}, {-r, top, r}, {r, top, r}}, {1, 1});  // a black roof straight overhead
    mesh.add({{-r, top, -r}, {r, top, r}, {r, top, -r}}, {1, 1});
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{albedo}, Material{Vec3f{0, 0, 0}}}});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    scene.sun = makeSun(90.0f, 0.0f, 0.5f, Vec3f{5, 5, 5});
    // Looking straight down from under the roof at a small patch of ground.
    Camera camera = makeLookAtCamera(Vec3f{0, 1, 0}, Vec3f{0, 0, 0}, 10.0f, 1.0f);
    RenderCounters counters;
    LinearImage image = renderCpu(scene.view(), camera, smallSettings(4), false, counters);
    for (const Vec3f& p : image.pixels) EXPECT_EQ(maxComponent(p), 0.0f);
}
