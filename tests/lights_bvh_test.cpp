// The light BVH and the colliders sampler (lights/light_bvh.h, lights/collider_lights.h): at
// several shading points the frequency of each light equals its pmf (Pearson's chi-square,
// tests/chi2_support.h), the pmfs of all lights sum to one, and every pick's pmf is the pmf the
// sampler reports for that light afterwards (what MIS asks when BSDF sampling finds it).
#include "chi2_support.h"
#include "lights/light_bvh_build.h"
#include "lights/light_sampler.h"
#include "lights_test_scenes.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace urbis;

namespace {

constexpr int kTests = 8;  // chi-square tests in this file (4 points x 2 samplers), for the Sidak correction

/// Shading points over the many-emitter plane and one among the lights, with their normals (the
/// last has none: a point in a medium).
const LightSampleContext kPoints[] = {
    {{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
    {{37.0f, 0.0f, -12.0f}, {0.0f, 1.0f, 0.0f}},
    {{-20.0f, 4.0f, 30.0f}, {0.6f, 0.0f, 0.8f}},
    {{5.0f, 5.5f, -40.0f}, {0.0f, 0.0f, 0.0f}},
};

/// Draws `samples` picks of `kind` at `ctx` and tests their counts against the pmfs (and that each
/// pick's reported pmf is the pmf of that light).
void expectChoiceFits(const SceneView& lights, LightSamplerKind kind, const LightSampleContext& ctx, uint32_t samples,
                      uint32_t seed) {
    const uint32_t count = lightCount(lights);
    std::vector<double> observed(count, 0.0), expected(count, 0.0);
    double total = 0;
    for (uint32_t i = 0; i < count; ++i) total += expected[i] = lightSelectionPmf(lights, kind, ctx, i);
    ASSERT_NEAR(total, 1.0, 1e-4);
    for (double& e : expected) e *= samples;
    SampleStream rng{seed, 0, 0};
    for (uint32_t s = 0; s < samples; ++s) {
        float pmf;
        const uint32_t i = selectLight(lights, kind, ctx, rng.draw(), pmf);
        ASSERT_LT(i, count);
        if (s < 5000) {
            ASSERT_EQ(pmf, lightSelectionPmf(lights, kind, ctx, i)) << "light " << i;
        }
        observed[i] += 1;
    }
    const chi2::Outcome outcome = chi2::pearson(observed, expected);
    EXPECT_GT(outcome.pValue, chi2::sidakLevel(kTests)) << outcome.message;
}

} // namespace

// 600 emitters (1,200 triangle lights) over a 120 m plane: the BVH's and the colliders' picks.
TEST(LightBvh, ChoiceFitsPmf) {
    Scene scene = test::manyEmitterScene(600, 120.0f);
    LightBuildOptions options;
    options.colliderRadius = 15.0f;
    buildLights(scene, options);
    const SceneView view = scene.view();
    ASSERT_EQ(lightCount(view), 1200u);
    ASSERT_EQ(scene.lightBvhNodes.size(), 2u * 1200u - 1u);
    uint32_t seed = 3;
    for (const LightSampleContext& ctx : kPoints)
        for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Colliders})
            expectChoiceFits(view, kind, ctx, 100000, seed++);
}

// The pmfs of every light sum to one at many points (with infinite lights: the sun and the sky,
// which take their share: by power for the BVH, fixed for the colliders), and the BVH's pick
// probabilities follow importance: a light overhead is likelier than the same light far away.
TEST(LightBvh, PmfsSumToOne) {
    Scene scene = test::manyEmitterScene(300, 80.0f);
    scene.sun = makeSun(30.0f, 60.0f, 2.0f, Vec3f{3, 3, 3});
    scene.sky = Sky{};
    LightBuildOptions options;
    options.skyMinShare = 0.0f;
    buildLights(scene, options);
    const SceneView lights = scene.view();
    ASSERT_EQ(lights.infiniteLights.size, 2u);
    const uint32_t count = lightCount(lights), sun = lights.lights.first<SunLight>(), sky = lights.lights.first<SkyLight>();
    double infinitePower = 0, finitePower = 0;
    for (uint32_t i = 0; i < count; ++i) (i == sun || i == sky ? infinitePower : finitePower) += lights.lightRecords[i].power;
    ASSERT_GT(finitePower, 1e-3 * infinitePower);   // the tree keeps a share worth testing
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int k = 0; k < 60; ++k) {
        const Vec3f p{(unit(rng) - 0.5f) * 100.0f, unit(rng) * 10.0f, (unit(rng) - 0.5f) * 100.0f};
        const Vec3f n = k % 4 == 0 ? Vec3f{} : normalize(Vec3f{unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f});
        for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Colliders}) {
            double sum = 0, infinite = 0;
            for (uint32_t i = 0; i < count; ++i) {
                const double pmf = lightSelectionPmf(lights, kind, {p, n}, i);
                sum += pmf;
                if (i == sun || i == sky) infinite += pmf;
            }
            EXPECT_NEAR(sum, 1.0, 1e-4) << "point " << k;
            // The BVH: the infinite lights' power against the tree's. The colliders: each infinite
            // light counts as much as the tree of the lights near the point (pbrt-v4's fixed share),
            // and where there are none the infinite lights take every pick.
            if (kind == LightSamplerKind::Bvh) EXPECT_NEAR(infinite, infinitePower / (infinitePower + finitePower), 1e-5);
            else EXPECT_TRUE(std::fabs(infinite - 1.0) < 1e-6 || std::fabs(infinite - 2.0 / 3.0) < 1e-6) << infinite;
        }
    }
}

// Two equal emitters, one overhead and one 50 m away: the BVH picks the near one far more often.
TEST(LightBvh, NearLightIsLikelier) {
    TriangleMesh mesh;
    test::addSquare(mesh, 1.0f, 5.0f, 1);
    mesh.add({Vec3f{49.5f, 5, -0.5f}, Vec3f{50.5f, 5, 0.5f}, Vec3f{50.5f, 5, -0.5f}}, {1, 1});
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{}, test::emitter(Vec3f{10, 10, 10})}});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    buildLights(scene);
    const SceneView lights = scene.view();
    ASSERT_EQ(lightCount(lights), 3u);
    const LightSampleContext ctx{{0, 0, 0}, {0, 1, 0}};
    EXPECT_GT(lightSelectionPmf(lights, LightSamplerKind::Bvh, ctx, 0), 20.0f * lightSelectionPmf(lights, LightSamplerKind::Bvh, ctx, 2));
}

// The build is deterministic and every light's trail leads to its own leaf.
TEST(LightBvh, TrailsLeadToLeaves) {
    Scene scene = test::manyEmitterScene(2000, 300.0f);
    buildLights(scene);
    Scene again = test::manyEmitterScene(2000, 300.0f);
    buildLights(again);
    ASSERT_EQ(scene.lightBvhNodes.size(), again.lightBvhNodes.size());
    EXPECT_EQ(0, std::memcmp(scene.lightBvhNodes.data(), again.lightBvhNodes.data(),
                             scene.lightBvhNodes.size() * sizeof(LightBvhNode)));
    for (uint32_t light = 0; light < scene.lightRecords.size(); ++light) {
        uint64_t trail = scene.lightBvhTrails[light];
        ASSERT_NE(trail, kNoLightTrail);
        uint32_t i = 0, depth = 0;
        while (!scene.lightBvhNodes[i].leaf()) {
            i = (trail & 1u) != 0 ? scene.lightBvhNodes[i].index() : i + 1;
            trail >>= 1;
            ++depth;
        }
        EXPECT_EQ(scene.lightBvhNodes[i].index(), light);
        EXPECT_LT(depth, 40u);
    }
}
