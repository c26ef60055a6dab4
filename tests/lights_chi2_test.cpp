// Every light's sampler against its pdf (Pearson's chi-square, tests/chi2_support.h): the sky's
// importance table, the sun's disk, emitting triangles seen from a point, and the light sampler's
// discrete choice, uniform and by power.
#include "chi2_support.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights_test_scenes.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

constexpr int kTests = 6;  // chi-square tests in this file, for the Sidak correction
constexpr uint32_t kSamples = 400000;

void expectFits(const chi2::DirectionSampler& sample, const chi2::DirectionPdf& pdf, const chi2::DirectionBins& bins,
                uint32_t samples, uint32_t seed) {
    const chi2::Outcome outcome = chi2::testDirections(sample, pdf, bins, samples, seed);
    EXPECT_GT(outcome.pValue, chi2::sidakLevel(kTests)) << outcome.message;
}

/// Distance along `dir` from `from` to triangle `t` (Moeller-Trumbore), or a negative number.
float hitDistance(const TriangleLight& t, Vec3f from, Vec3f dir) {
    const Vec3f e1 = t.p1 - t.p0, e2 = t.p2 - t.p0, p = cross(dir, e2);
    const float det = dot(e1, p);
    if (fabsf(det) < 1e-12f) return -1;
    const Vec3f s = from - t.p0, q = cross(s, e1);
    const float u = dot(s, p) / det, v = dot(dir, q) / det;
    if (u < 0 || v < 0 || u + v > 1) return -1;
    return dot(e2, q) / det;
}

/// Bins uniform in theta about the sky map's axis (+y) and from its origin of phi (+x towards +z),
/// aligned with the table's cells when the counts divide its 64 x 128: the midpoint rule
/// integrates the pdf exactly there.
chi2::DirectionBins skyMapBins(int thetaBins, int phiBins, double cosMin, int subdivisions) {
    chi2::DirectionBins bins;
    bins.frame = Frame{Vec3f{1, 0, 0}, Vec3f{0, 0, 1}, Vec3f{0, 1, 0}};
    // Rows uniform in cos theta and columns in phi, as the sky's equal-area map has them: its pdf is
    // constant in each bin, which the midpoint rule integrates exactly.
    bins.smooth = false;
    bins.cosMin = cosMin;
    bins.thetaBins = thetaBins;
    bins.phiBins = phiBins;
    bins.subdivisions = subdivisions;
    return bins;
}

/// The first light of an emitting triangle of `material` (kNoLight if none).
uint32_t firstLightOf(const Scene& scene, uint32_t material) {
    for (const EmitterTriangle& e : scene.emitterTriangles)
        if (scene.triangleInfo[e.triangle].material == material) return e.light;
    return kNoLight;
}

/// Lights: a sun, the default sky, and three emitting surfaces of different sizes and radiance.
Scene lightsScene() {
    TriangleMesh mesh;
    test::addSquare(mesh, 2.0f, 3.0f, 1);
    mesh.add({Vec3f{2, 1, 0}, Vec3f{3, 1, 0}, Vec3f{2, 2.5f, 0.5f}}, {1, 1});  // same material: one surface
    test::addSquare(mesh, 6.0f, 8.0f, 2);
    test::addSquare(mesh, 1.0f, -2.0f, 3);
    Scene scene = Scene::build({.mesh = mesh,
                                .materials = {Material{}, test::emitter(Vec3f{4, 3, 2}),
                                              test::emitter(Vec3f{0.5f, 0.5f, 0.5f}), test::emitter(Vec3f{20, 20, 20})}});
    scene.sun = makeSun(30.0f, 60.0f, 2.0f, Vec3f{3, 3, 3});
    LightBuildOptions everyLight;
    everyLight.skyMinShare = 0.0f;  // the sky too, though the sun outshines it
    buildLights(scene, everyLight);
    return scene;
}

} // namespace

TEST(LightsChi2, SkyFromItsTable) {
    Scene scene = Scene::build({.materials = {Material{}}});
    buildLights(scene);
    const SceneView view = scene.view();
    ASSERT_NE(view.lights.first<SkyLight>(), kNoLight);
    ASSERT_FALSE(view.skyTable.size == 0);
    const LightRecord sky = lightRecord(view, view.lights.first<SkyLight>());
    const chi2::DirectionBins bins = skyMapBins(32, 32, -1.0, 12);
    uint32_t mismatches = 0;  // a direction rounded back across a cell's edge reads its neighbour's pdf
    expectFits(
        [&](float u0, float u1, float u2, Vec3f& d) {
            LightSample s;
            if (!sampleLight(view, sky, Vec3f{}, u0, u1, u2, s)) return false;
            mismatches += fabsf(s.pdf - lightPdf(view, sky, s.dir, 0, 0)) > 1e-3f * s.pdf;
            d = s.dir;
            return true;
        },
        [&](Vec3f d) { return double(lightPdf(view, sky, d, 0, 0)); }, bins, kSamples, 11);
    EXPECT_LT(mismatches, kSamples / 1000) << "sampled pdf and lightPdf of the same direction differ";
    // The table follows the sky: a sample just above the horizon, where the sky is brightest, is
    // likelier than one below it; the zenith, about as bright as the mean, is left to BSDF sampling.
    const float nearHorizon = lightPdf(view, sky, normalize(Vec3f{0, 0.05f, 1}), 0, 0);
    EXPECT_GT(nearHorizon, lightPdf(view, sky, Vec3f{0, -0.6f, 0.8f}, 0, 0));
    EXPECT_LT(lightPdf(view, sky, normalize(Vec3f{0.01f, 1, 0}), 0, 0), 0.01f * nearHorizon);
}

TEST(LightsChi2, SunDisk) {
    Scene scene = lightsScene();
    const SceneView view = scene.view();
    const LightRecord sun = lightRecord(view, view.lights.first<SunLight>());
    ASSERT_EQ(sun.kind, kLightKindOf<SunLight>);
    chi2::DirectionBins bins;
    bins.frame = Frame::fromZ(scene.sun.direction);
    bins.cosMin = scene.sun.cosHalfAngle;
    bins.smooth = false;
    expectFits(
        [&](float u0, float u1, float u2, Vec3f& d) {
            LightSample s;
            if (!sampleLight(view, sun, Vec3f{}, u0, u1, u2, s)) return false;
            d = s.dir;
            return true;
        },
        [&](Vec3f d) { return double(lightPdf(view, sun, d, 0, 0)); }, bins, kSamples, 12);
}

// A triangle of the first surface seen from a point below it, and of the brightest one from the
// side: directions binned about the way to each.
TEST(LightsChi2, EmissiveSurfaces) {
    Scene scene = lightsScene();
    const SceneView view = scene.view();
    ASSERT_EQ(scene.emissiveSurfaces.size(), 7u);  // one per emitting triangle
    for (uint32_t material : {1u, 3u}) {
        const uint32_t index = firstLightOf(scene, material);
        ASSERT_NE(index, kNoLight);
        const LightRecord light = lightRecord(view, index);
        const EmissiveSurface& surface = view.emissiveSurfaces[light.index];
        const Vec3f from = material == 1 ? Vec3f{0.5f, 0.0f, 0.2f} : Vec3f{1.0f, -1.0f, 0.5f};
        const Bounds3f box = lightBoundsOf(scene, light).bounds;
        chi2::DirectionBins bins;
        bins.frame = Frame::fromZ(normalize(box.centre() - from));
        bins.cosMin = material == 1 ? 0.2 : 0.5;
        bins.subdivisions = 32;
        bins.smooth = false;
        auto pdf = [&](Vec3f d) {
            double sum = 0;
            for (uint32_t i = 0; i < surface.triangleCount; ++i) {
                const TriangleLight& t = view.triangleLights[surface.firstTriangle + i];
                const float distance = hitDistance(t, from, d);
                if (distance > 0)
                    sum += double(lightPdf(view, light, d, distance, dot(normalize(cross(t.p1 - t.p0, t.p2 - t.p0)), d)));
            }
            return sum;
        };
        expectFits(
            [&](float u0, float u1, float u2, Vec3f& d) {
                LightSample s;
                if (!sampleLight(view, light, from, u0, u1, u2, s)) return false;
                EXPECT_EQ(s.radiance.x, surface.emission.x);
                d = s.dir;
                return true;
            },
            pdf, bins, 200000, 13 + material);
    }
}

// The light sampler's choice: counts per light against its pmf, for both kinds.
TEST(LightsChi2, LightSamplerChoice) {
    Scene scene = lightsScene();
    const SceneView view = scene.view();
    const uint32_t n = lightCount(view);
    ASSERT_EQ(n, 9u);  // sun, sky, seven emitting triangles
    for (LightSamplerKind kind : {LightSamplerKind::Uniform, LightSamplerKind::Power}) {
        std::vector<double> observed(n, 0.0), expected(n, 0.0);
        double total = 0;
        for (uint32_t i = 0; i < n; ++i) total += expected[i] = lightSelectionPmf(view, kind, {}, i);
        EXPECT_NEAR(total, 1.0, 1e-5);
        for (double& e : expected) e *= kSamples;
        SampleStream rng{21, 0, 0};
        for (uint32_t s = 0; s < kSamples; ++s) {
            float pmf;
            const uint32_t i = selectLight(view, kind, {}, rng.draw(), pmf);
            ASSERT_LT(i, n);
            EXPECT_FLOAT_EQ(pmf, lightSelectionPmf(view, kind, {}, i));
            observed[i] += 1;
        }
        const chi2::Outcome outcome = chi2::pearson(observed, expected);
        EXPECT_GT(outcome.pValue, chi2::sidakLevel(kTests)) << outcome.message;
    }
    // By power the small bright source is picked more often than the large dim one, which has 36
    // times its area but a fortieth of its radiance.
    const uint32_t bright = firstLightOf(scene, 3), dim = firstLightOf(scene, 2);
    EXPECT_GT(lightSelectionPmf(view, LightSamplerKind::Power, {}, bright),
              lightSelectionPmf(view, LightSamplerKind::Power, {}, dim));
}

// Each light's pdf integrates to one over the directions it covers (the sky's over the sphere,
// exactly on bins aligned with its table; the sun's over its disk; a surface's from a point).
TEST(LightsPdf, IntegratesToOne) {
    Scene scene = lightsScene();
    const SceneView view = scene.view();
    const LightRecord sky = lightRecord(view, view.lights.first<SkyLight>()), sun = lightRecord(view, view.lights.first<SunLight>());
    EXPECT_NEAR(chi2::integratePdf([&](Vec3f d) { return double(lightPdf(view, sky, d, 0, 0)); }, skyMapBins(64, 128, -1.0, 2)),
                1.0, 1e-4);
    chi2::DirectionBins disk;
    disk.frame = Frame::fromZ(scene.sun.direction);
    disk.cosMin = scene.sun.cosHalfAngle;
    disk.smooth = false;
    EXPECT_NEAR(chi2::integratePdf([&](Vec3f d) { return double(lightPdf(view, sun, d, 0, 0)); }, disk), 1.0, 1e-3);
    const LightRecord bright = lightRecord(view, firstLightOf(scene, 3));
    const EmissiveSurface& brightSurface = view.emissiveSurfaces[bright.index];
    const TriangleLight* triangles = view.triangleLights.data + brightSurface.firstTriangle;
    const Vec3f from{1.0f, -1.0f, 0.5f};
    chi2::DirectionBins towards;
    towards.frame = Frame::fromZ(normalize(lightBoundsOf(scene, bright).bounds.centre() - from));
    towards.cosMin = 0.5;
    towards.thetaBins = towards.phiBins = 64;
    towards.smooth = false;
    auto pdf = [&](Vec3f d) {
        double sum = 0;
        for (uint32_t i = 0; i < brightSurface.triangleCount; ++i) {
            const float distance = hitDistance(triangles[i], from, d);
            const Vec3f n = normalize(cross(triangles[i].p1 - triangles[i].p0, triangles[i].p2 - triangles[i].p0));
            if (distance > 0) sum += double(lightPdf(view, bright, d, distance, dot(n, d)));
        }
        return sum;
    };
    EXPECT_NEAR(chi2::integratePdf(pdf, towards), 1.0, 5e-3);
}

// The sky joins the light list where its table's power is at least half of the sun's and its own
// together: under the default sun it is left to BSDF sampling, at night (no sun) it is light-sampled.
TEST(LightsBuild, SkyJoinsWhereItOutshinesTheSun) {
    Scene scene = Scene::build({.materials = {Material{}}});
    scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    buildLights(scene);
    EXPECT_NE(scene.lights.first<SunLight>(), kNoLight);
    EXPECT_EQ(scene.lights.first<SkyLight>(), kNoLight);
    scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{0, 0, 0});
    buildLights(scene);
    EXPECT_EQ(scene.lights.first<SunLight>(), kNoLight);
    EXPECT_NE(scene.lights.first<SkyLight>(), kNoLight);
}

// Over an infinite ground plane nothing below the horizon can be seen from above it: the sky's
// table leaves those directions to BSDF sampling (pdf 0) and integrates to one above.
TEST(LightsPdf, SkyAboveTheGroundSamplesTheUpperHemisphere) {
    Scene scene = Scene::build({.materials = {Material{}}, .grounds = {GroundRecord::around(0.0f, 0.0f, 0.0f, 0)}});
    buildLights(scene);
    const SceneView view = scene.view();
    const LightRecord sky = lightRecord(view, view.lights.first<SkyLight>());
    EXPECT_EQ(lightPdf(view, sky, normalize(Vec3f{0.3f, -0.2f, 0.5f}), 0, 0), 0.0f);
    EXPECT_NEAR(chi2::integratePdf([&](Vec3f d) { return double(lightPdf(view, sky, d, 0, 0)); }, skyMapBins(32, 128, 0.0, 2)),
                1.0, 1e-4);
    SampleStream rng{3, 0, 0};
    for (int i = 0; i < 1000; ++i) {
        LightSample s;
        ASSERT_TRUE(sampleLight(view, sky, Vec3f{}, rng.draw(), rng.draw(), rng.draw(), s));
        EXPECT_GE(s.dir.y, 0.0f);
    }
}
