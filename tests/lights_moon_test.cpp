// The moon as a light: the sun's record and functions (lights/sun_light.h) for a second disk, in the
// light list when up, light-sampled to the analytic irradiance, seen by camera rays; and its
// brightness against the sun's from a description's date, time and place.
#include "cpu/cpu_renderer.h"
#include "description/celestial_parts.h"
#include "lights/light_build.h"
#include "lights/sun_light.h"
#include "math/constants.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

Scene moonlitPlane(Vec3f albedo, const Sun& moon) {
    TriangleMesh mesh;
    const float h = 200.0f;
    const Vec3f a{-h, 0, -h}, b{h, 0, -h}, c{h, 0, h}, d{-h, 0, h};
    mesh.add({a, d, c}, {0, 0});
    mesh.add({a, c, b}, {0, 0});
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{albedo}}});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    scene.sun = Sun{};  // off
    scene.night.moon = moon;
    buildLights(scene);
    return scene;
}

RenderSettings settingsOf(uint32_t width, uint32_t height, uint32_t spp) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.spp = spp;
    return s;
}

// A Lambertian plane under the moon alone: rho E <cos> / pi, with the disk's mean cosine
// sin(elevation) (1 + cos r) / 2, as for the sun (render_analytic_test).
TEST(MoonLight, LightsAPlaneAsTheAnalyticIrradianceSays) {
    const Vec3f albedo{0.7f, 0.6f, 0.5f}, irradiance{2e-5f, 1.8e-5f, 1.6e-5f};
    const float elevation = 40.0f, radius = 0.26f;
    const Scene scene = moonlitPlane(albedo, makeSun(elevation, 200.0f, radius, irradiance));
    ASSERT_NE(scene.lights.first<MoonLight>(), kNoLight);
    EXPECT_EQ(scene.lights.first<SunLight>(), kNoLight);
    const float meanCosine = std::sin(elevation * kPi / 180.0f) * 0.5f * (1.0f + std::cos(radius * kPi / 180.0f));
    const Vec3f expected = albedo * irradiance * (meanCosine / kPi);
    const Camera camera = cameraFromHeading(Vec3f{0, 10, 0}, 30.0f, -60.0f, 40.0f, 32.0f / 24.0f);
    RenderCounters counters;
    const LinearImage image = renderCpu(scene.view(), camera, settingsOf(32, 24, 16), false, counters);
    for (const Vec3f& p : image.pixels)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c] / expected[c], 1.0f, 0.01f);
}

// Camera rays see the disk (the sun's they do not): a camera looking at the moon's centre sees its
// radiance in the middle pixel and black sky at the corners.
TEST(MoonLight, CameraRaysSeeTheDisk) {
    const Sun moon = makeSun(30.0f, 120.0f, 0.26f, Vec3f{1e-5f, 1e-5f, 1e-5f});
    const Scene scene = moonlitPlane(Vec3f{0.5f, 0.5f, 0.5f}, moon);
    const Camera camera = makeLookAtCamera(Vec3f{0, 10, 0}, Vec3f{0, 10, 0} + moon.direction, 2.0f, 1.0f);
    RenderCounters counters;
    const LinearImage image = renderCpu(scene.view(), camera, settingsOf(33, 33, 4), false, counters);
    EXPECT_NEAR(image.pixels[16 * 33 + 16].x / moon.radiance.x, 1.0f, 1e-4f);
    EXPECT_EQ(maxComponent(image.pixels[0]), 0.0f);
}

TEST(MoonLight, LeavesTheListBelowTheHorizon) {
    const Scene scene = moonlitPlane(Vec3f{0.5f, 0.5f, 0.5f}, Sun{});
    EXPECT_EQ(scene.lights.first<MoonLight>(), kNoLight);
}

// The full moon of 2024-04-23 23:49 UT (US Naval Observatory, "Phases of the Moon"), seen from
// Prague an hour after midnight: up in the south-east, lit in full, and its disk gives the sun's
// irradiance times the Lambertian sphere's share, about 1/400,000 (the magnitudes -12.7 against
// -26.7: astro_ephemeris_test).
TEST(MoonLight, FullMoonIsAbout400000TimesFainterThanTheSun) {
    SceneDescription d;
    d.astronomy.time = "2024-04-24T01:49+02:00";
    const CelestialLights lights = celestialLightsOf(d, GeoOrigin{});
    ASSERT_TRUE(sunEnabled(lights.night.moon));
    EXPECT_GT(lights.night.moon.direction.y, 0.1f);
    EXPECT_FALSE(sunEnabled(lights.sun));  // the sun is down: its disk leaves the scene
    const double solidAngle = 2.0 * double(kPi) * (1.0 - double(lights.night.moon.cosHalfAngle));
    const double ratio = double(luminance(lights.night.moon.radiance)) * solidAngle / double(luminance(d.sun.irradiance));
    EXPECT_GT(ratio, 1.0 / 480000.0);
    EXPECT_LT(ratio, 1.0 / 340000.0);
}

// Without a time the description's sun is today's, and there is no moon and there are no stars.
TEST(MoonLight, NoTimeMeansTheDefaultSunAlone) {
    const SceneDescription d;
    const CelestialLights lights = celestialLightsOf(d, GeoOrigin{});
    const Sun expected = makeSun(d.sun.elevation, d.sun.azimuth, d.sun.angularRadius, d.sun.irradiance);
    EXPECT_EQ(lights.sun.direction.x, expected.direction.x);
    EXPECT_EQ(lights.sun.radiance.y, expected.radiance.y);
    EXPECT_FALSE(sunEnabled(lights.night.moon));
    EXPECT_EQ(lights.night.stars.magnitudeZeroIrradiance, 0.0f);
}

// --sun's angles win over the time's sun (sun_from_time false), the moon and stars still follow the time.
TEST(MoonLight, SunAnglesOverrideTheTimesSun) {
    SceneDescription d;
    d.astronomy.time = "2024-06-21T12:00+02:00";
    d.astronomy.location = std::array<double, 2>{14.42, 50.09};
    const CelestialLights fromTime = celestialLightsOf(d, GeoOrigin{});
    EXPECT_GT(fromTime.sun.direction.y, std::sin(60.0f * kPi / 180.0f));  // near noon at midsummer: about 63 degrees
    d.astronomy.sunFromTime = false;
    const CelestialLights fromAngles = celestialLightsOf(d, GeoOrigin{});
    EXPECT_NEAR(fromAngles.sun.direction.y, std::sin(d.sun.elevation * kPi / 180.0f), 1e-6f);
    EXPECT_GT(fromAngles.night.stars.magnitudeZeroIrradiance, 0.0f);
}

} // namespace
} // namespace urbis
