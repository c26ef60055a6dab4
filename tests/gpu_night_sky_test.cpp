// The moon and the stars on the GPU: the same night view (a plane under the full moon of
// 2024-04-24 over Prague, the moon's disk and the star field in view) path traced on both backends.
#include "gpu_test_support.h"

#include "description/celestial_parts.h"
#include "lights/light_build.h"

using namespace urbis;

// Metric: per-pixel luminance. The stars' map (atanf, sqrtf) and the moon's disk test run on the
// GPU's approximate shading math, so a sample near a star's or the disk's edge may land on the
// other side: the mean absolute difference stays under 1 % of the mean luminance, and the pixel at
// the moon's centre (inside the disk for every sample) agrees within 0.1 %.
TEST(GpuNightSky, MoonAndStarsMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    SceneDescription d;
    d.astronomy.time = "2024-04-24T01:49+02:00";
    const CelestialLights celestial = celestialLightsOf(d, GeoOrigin{});
    TriangleMesh mesh;
    const float h = 500.0f;
    mesh.add({{-h, 0, -h}, {-h, 0, h}, {h, 0, h}}, {0, 0});
    mesh.add({{-h, 0, -h}, {h, 0, h}, {h, 0, -h}}, {0, 0});
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{Vec3f{0.5f, 0.5f, 0.5f}}}});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    scene.sun = celestial.sun;
    scene.night = celestial.night;
    buildLights(scene);
    ASSERT_NE(scene.lights.first<MoonLight>(), kNoLight);
    const Vec3f eye{0, 2, 0};
    const Camera camera = makeLookAtCamera(eye, eye + celestial.night.moon.direction, 40.0f, 161.0f / 121.0f);
    LinearImage cpu, gpu;
    test::expectParity(test::renderOnBoth(scene, camera, 161, 121, 16, "night sky", cpu, gpu), 0.01);
    ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
    const size_t centre = 60 * 161 + 80;
    EXPECT_NEAR(luminance(gpu.pixels[centre]) / luminance(cpu.pixels[centre]), 1.0, 1e-3);
    EXPECT_NEAR(luminance(cpu.pixels[centre]) / luminance(celestial.night.moon.radiance), 1.0, 1e-4);
}
