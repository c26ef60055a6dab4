// MIS weights of the path tracer: for one direction, the weight of the light sample and the weight
// of the BSDF sample that could both find it sum to one, for every light kind, material and
// number of light samples; and the power heuristic's limits.
#include "integrators/path_tracer.h"
#include "lights_test_scenes.h"

#include <gtest/gtest.h>

using namespace urbis;

TEST(LightsMis, PowerHeuristicLimits) {
    EXPECT_FLOAT_EQ(powerHeuristic(1, 2, 1, 2), 0.5f);
    EXPECT_FLOAT_EQ(powerHeuristic(1, 1, 1, 3), 0.1f);   // 1 / (1 + 9)
    EXPECT_FLOAT_EQ(powerHeuristic(2, 1, 1, 2), 0.5f);   // counts multiply pdfs
    EXPECT_EQ(powerHeuristic(1, 0, 1, 1), 0.0f);         // the strategy cannot make this direction
    EXPECT_EQ(powerHeuristic(1, 1, 1, 0), 1.0f);         // only this one can
    EXPECT_EQ(powerHeuristic(1, 3e30f, 1, 1), 1.0f);     // huge pdfs stay finite
    EXPECT_EQ(powerHeuristic(1, 1, 1, 3e30f), 0.0f);
}

TEST(LightsMis, WeightsOfBothStrategiesSumToOne) {
    TriangleMesh mesh;
    test::addSquare(mesh, 2.0f, 3.0f, 1);
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{}, test::emitter(Vec3f{4, 3, 2})}});
    scene.sun = makeSun(50.0f, 60.0f, 3.0f, Vec3f{3, 3, 3});
    LightBuildOptions everyLight;
    everyLight.skyMinShare = 0.0f;  // the sky too, though the sun outshines it
    buildLights(scene, everyLight);
    const SceneView view = scene.view();
    Material glossy;
    glossy.kind = MaterialKind::Glossy;
    glossy.albedo = Vec3f{0.3f, 0.3f, 0.3f};
    glossy.specular = Vec3f{0.5f, 0.5f, 0.5f};
    glossy.exponent = 10;
    const Vec3f n{0, 1, 0}, wo = normalize(Vec3f{0.4f, 0.8f, 0.1f}), from{0.2f, 0.0f, 0.1f};
    SampleStream rng{5, 0, 0};
    int checked = 0;
    for (const Material& m : {Material{}, glossy})
        for (uint32_t lightSamples : {1u, 3u})
            for (LightSamplerKind kind : {LightSamplerKind::Uniform, LightSamplerKind::Power, LightSamplerKind::Bvh,
                                          LightSamplerKind::Colliders})
                for (uint32_t light = 0; light < lightCount(view); ++light)
                    for (int i = 0; i < 50; ++i) {
                        const LightRecord record = lightRecord(view, light);
                        LightSample s;
                        if (!sampleLight(view, record, from, rng.draw(), rng.draw(), rng.draw(), s)) continue;
                        const float pmf = lightSelectionPmf(view, kind, {from, n}, light);
                        const float lightPdfTotal = pmf * s.pdf, bsdf = bsdfPdf(m, wo, s.dir, n);
                        if (!(bsdf > 0.0f)) continue;
                        // The same direction as the BSDF would find it: the light's pdf from the hit.
                        const float cosLight = record.kind == kLightKindOf<EmissiveSurfaceLight> ? -s.dir.y : 0.0f;
                        const float found = pmf * lightPdf(view, record, s.dir, s.distance, cosLight);
                        EXPECT_NEAR(found, lightPdfTotal, 1e-3f * lightPdfTotal);
                        // The BSDF sample's weight as the path tracer gives it (the sun's: none, without a pmf).
                        RenderSettings settings;
                        settings.lightSamples = lightSamples;
                        settings.lightSampler = kind;
                        const BounceInfo bounce{bsdf, false, true, {from, n}};
                        const float bsdfWeight = dispatchLight(record.kind, [&](auto k) {
                            return foundWeight<typename decltype(k)::Light>(view, settings, bounce, [&] { return light; },
                                                                            s.dir, s.distance, cosLight);
                        });
                        const float sum = lightSampleWeight(record.kind, lightSamples, lightPdfTotal, bsdf) + bsdfWeight;
                        EXPECT_NEAR(sum, 1.0f, 1e-5f);
                        ++checked;
                    }
    EXPECT_GT(checked, 500);
    // A specular bounce or the camera ray counts what it finds in full.
    RenderSettings settings;
    settings.lightSamples = 1;
    const auto firstLight = [] { return 0u; };
    EXPECT_EQ(foundWeight<EmissiveSurfaceLight>(view, settings, BounceInfo{}, firstLight, Vec3f{0, 1, 0}, 1.0f, 1.0f), 1.0f);
    EXPECT_EQ(foundWeight<SunLight>(view, settings, BounceInfo{}, firstLight, Vec3f{0, 1, 0}, 0.0f, 0.0f), 1.0f);
}
