// The night's lights: street lamps (flux of their profiles, the analytic irradiance they give a
// plane), lit windows (shares by hour and use, their colours, a window's power), walls as aggregate
// lights (the pick of a lit cell and the sampler against their pmf and pdf, a wall's power the sum
// of its windows') and a night scene that converges to the same image with and without light
// sampling of its windows.
#include "chi2_support.h"
#include "citygen/window_schedule.h"
#include "cpu/cpu_renderer.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights/light_build.h"
#include "lights_test_scenes.h"
#include "night_test_scenes.h"
#include "scene/camera_framing.h"
#include "scene/lamp_emission.h"

#include <gtest/gtest.h>

#include <random>

using namespace urbis;
using test::nightScene;
using test::testWall;
using test::wallMaterials;

namespace {

constexpr LampShape kShapes[] = {LampShape::Cobra, LampShape::Globe, LampShape::Lantern, LampShape::Cone, LampShape::Flat};

/// A lamp with its head on nothing (no pole, no arm) `height` above the origin.
LampRecord floatingLamp(LampShape shape, float height) {
    return LampRecord{.base = {0, 0, 0}, .height = height, .armLength = 0.0f, .poleRadius = 0.0f, .headSize = 0.6f,
                      .material = 1, .colourTemperature = 3000.0f, .luminousFlux = 12000.0f, .shape = shape};
}

/// Plane material 0, the lamp's three after it.
std::vector<Material> planeAndLampMaterials(Vec3f albedo) {
    return {Material{albedo}, Material{{0.5f, 0.5f, 0.5f}}, Material{{0.2f, 0.2f, 0.2f}}, Material{{0.8f, 0.8f, 0.8f}}};
}

Vec3f imageMean(const LinearImage& image) {
    Vec3f sum;
    for (const Vec3f& p : image.pixels) sum += p;
    return sum / float(image.pixels.size());
}

} // namespace

// The intensity of every head's profile, integrated over the sphere, is the lamp's luminous flux in
// the renderer's units (lumens / kLuxPerUnit), in luminance; full-cutoff heads send nothing upwards.
TEST(NightLamps, ProfileCarriesTheLuminousFlux) {
    std::vector<LampRecord> lamps;
    for (LampShape shape : kShapes) lamps.push_back(floatingLamp(shape, 6.0f));
    Scene scene = nightScene(TriangleMesh{}, planeAndLampMaterials({0.5f, 0.5f, 0.5f}), {}, lamps);
    buildLights(scene);
    ASSERT_EQ(scene.lampLights.size(), lamps.size());
    lamps = scene.lamps;   // the scene's lamps are in leaf order, and so are their lights
    for (size_t i = 0; i < lamps.size(); ++i) {
        const LampEmitter& lamp = scene.lampLights[i];
        double flux = 0;
        const int n = 2000;
        for (int k = 0; k < n; ++k) {   // midpoint rule in cos theta; the profile does not depend on phi
            const float c = -1.0f + (float(k) + 0.5f) * 2.0f / float(n);
            flux += double(luminance(lampIntensity(lamp, {std::sqrt(1 - c * c), c, 0.0f}))) * 2.0 * M_PI * 2.0 / n;
        }
        EXPECT_NEAR(flux / (lamps[i].luminousFlux / kLuxPerUnit), 1.0, 2e-3) << "shape " << int(lamps[i].shape);
        EXPECT_EQ(scene.lightRecords[scene.lights.first<LampLight>() + i].power, lamps[i].luminousFlux / kLuxPerUnit);
        const bool cutoff = lamps[i].shape == LampShape::Cobra || lamps[i].shape == LampShape::Flat ||
                            lamps[i].shape == LampShape::Cone;
        EXPECT_EQ(maxComponent(lampIntensity(lamp, normalize(Vec3f{1, 0.01f, 0}))) == 0.0f, cutoff);
    }
}

// A lamp above a Lambertian plane: the radiance of the plane at points below it, 45 and 70 degrees
// off, is rho / pi times the analytic irradiance I(theta) cos(theta) / d^2, within 1 %. Each point
// is seen by a camera with a field of view of a hundredth of a degree; only direct light (one vertex).
TEST(NightLamps, IrradianceOnAPlaneIsAnalytic) {
    const Vec3f albedo{0.6f, 0.5f, 0.4f};
    const float h = 6.0f;
    TriangleMesh mesh;
    test::addSquare(mesh, 400.0f, 0.0f, 0);
    for (LampShape shape : {LampShape::Cobra, LampShape::Globe, LampShape::Flat}) {
        Scene scene = nightScene(mesh, planeAndLampMaterials(albedo), {}, {floatingLamp(shape, h)});
        buildLights(scene);
        ASSERT_NE(scene.lights.first<LampLight>(), kNoLight);
        const LampEmitter lamp = scene.lampLights[0];
        for (float angle : {0.0f, 45.0f, 70.0f}) {
            if (shape == LampShape::Globe && angle == 0.0f) continue;   // its collar shades the ground within 24 degrees of straight down
            const float x = (lamp.position.y) * std::tan(angle * float(M_PI) / 180.0f);
            const Vec3f p{x, 0.0f, 0.0f};
            const Vec3f toLamp = lamp.position - p;
            const float d2 = dot(toLamp, toLamp), cosine = toLamp.y / std::sqrt(d2);
            const Vec3f expected = albedo / float(M_PI) * lampIntensity(lamp, -normalize(toLamp)) * (cosine / d2);
            const Camera camera = cameraFromHeading(p + Vec3f{0.0f, 3.0f, 3.0f}, 0.0f, -45.0f, 0.01f, 1.0f);
            RenderSettings settings;
            settings.width = settings.height = 2;
            settings.spp = 4;
            settings.maxDepth = 1;
            RenderCounters counters;
            const Vec3f got = imageMean(renderCpu(scene.view(), camera, settings, false, counters));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c] / expected[c], 1.0f, 0.01f) << "shape " << int(shape) << ", " << angle << " deg, channel " << c;
        }
    }
}

// The glass shows the lamp's intensity over its projected area: seen from afar, its radiance times
// its projected solid angle is the irradiance the point gives there.
TEST(NightLamps, GlassRadianceCarriesTheIntensity) {
    for (LampShape shape : kShapes) {
        Scene scene = nightScene(TriangleMesh{}, planeAndLampMaterials({0.5f, 0.5f, 0.5f}), {}, {floatingLamp(shape, 6.0f)});
        buildLights(scene);
        const LampEmitter& lamp = scene.lampLights[0];
        for (Vec3f out : {Vec3f{0, -1, 0}, normalize(Vec3f{1, -1, 0}), normalize(Vec3f{1, -0.2f, 0.3f})}) {
            const Vec3f L = lampGlassRadiance(lamp, out);
            const Vec3f I = lampIntensity(lamp, out);
            EXPECT_NEAR(luminance(L) * lampGlassProjectedArea(lamp, out), luminance(I), 1e-4f * luminance(I));
        }
    }
}

// The colours of a room's temperatures are the blackbody's.
TEST(NightWindows, ColoursAreBlackbodies) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(kWindowWarm[c], blackbodyRgb(2700.0f)[c], 1e-3f);
        EXPECT_NEAR(kWindowCool[c], blackbodyRgb(4000.0f)[c], 1e-3f);
    }
}

// Over many windows the lit share is the table's (docs/facades.md § Lit windows) for each use and
// hour, within 1 % (binomial: 30,000 cells give a standard error under 0.3 %); the table's shape:
// evening most, deep night few, offices dark after hours and lit by day, shops in opening hours.
TEST(NightWindows, LitSharesFollowTheHourAndUse) {
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Residential, 20.0f), 0.65f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Residential, 3.0f), 0.05f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Residential, 12.0f), 0.05f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Office, 11.0f), 0.70f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Office, 22.0f), 0.06f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Shop, 14.0f), 0.85f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Shop, 23.0f), 0.02f);
    EXPECT_FLOAT_EQ(litShopWindowShare(2.0f), 0.50f);
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Residential, 19.5f), 0.625f);   // between 19 h and 20 h
    EXPECT_FLOAT_EQ(litRoomShare(WindowUse::Residential, 24.0f), litRoomShare(WindowUse::Residential, 0.0f));
    EXPECT_EQ(windowUseOf(BuildingType::Apartments), WindowUse::Residential);
    EXPECT_EQ(windowUseOf(BuildingType::Office), WindowUse::Office);
    EXPECT_EQ(windowUseOf(BuildingType::Retail), WindowUse::Shop);
    for (WindowUse use : {WindowUse::Residential, WindowUse::Office, WindowUse::Shop, WindowUse::Mixed})
        for (float hour : {3.0f, 12.0f, 20.0f, 23.5f}) {
            uint64_t lit = 0, cells = 0;
            for (uint32_t seed = 0; seed < 100; ++seed) {
                const WallRecord w = testWall(20, 15, litRoomShare(use, hour), seed * 7919u + 3u);
                for (uint32_t f = 0; f < w.floors; ++f)
                    for (uint32_t s = 0; s < w.slots; ++s, ++cells) lit += cellLit(w, cellLayout(w, f, s));
            }
            EXPECT_NEAR(double(lit) / double(cells), litRoomShare(use, hour), 0.01) << int(use) << " at " << hour << " h";
        }
}

// A window's power is pi times its area times its mean luminance: the luminance averaged over its
// glass (curtain and noise included) by a fine grid matches windowPower within 2 %; a wall's
// light carries the sum over its lit windows.
TEST(NightWindows, WallPowerIsTheSumOfItsLitWindows) {
    const WallRecord w = testWall(12, 8, 0.5f, 4242u);
    const std::vector<Material> materials = wallMaterials();
    const Vec3f room = materials[2 + uint32_t(FacadeMaterial::RoomLit)].emission;
    double sum = 0, integrated = 0;
    uint32_t lit = 0;
    for (uint32_t f = 0; f < w.floors; ++f)
        for (uint32_t s = 0; s < w.slots; ++s) {
            const CellLayout c = cellLayout(w, f, s);
            if (!cellLit(w, c)) continue;
            const WindowRect r = windowRect(w, c);
            const WindowLook look = windowLook(w, f, s);
            const int n = 64;
            double mean = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    mean += luminance(windowRadiance(look, r, room, r.u0 + (r.u1 - r.u0) * (i + 0.5f) / n,
                                                     r.v0 + (r.v1 - r.v0) * (j + 0.5f) / n));
            integrated += M_PI * r.area() * mean / (n * n);
            sum += windowPower(look, r, room);
            ++lit;
        }
    EXPECT_NEAR(integrated / sum, 1.0, 0.02);
    TriangleMesh mesh;
    Scene scene = nightScene(mesh, materials, {w}, {});
    buildLights(scene);
    ASSERT_NE(scene.lights.first<WindowLight>(), kNoLight);
    EXPECT_NEAR(scene.lightRecords[scene.lights.first<WindowLight>()].power / sum, 1.0, 1e-4);
    EXPECT_EQ(scene.lightRecords[scene.lights.first<WindowLight>()].litCells, lit);
}

// The pick of a lit cell (uniform tries, the first lit one kept) against its pmf, on a wall whose
// rooms are few lit (7 %: the deep night's share, where the tries reach their cap) and on one half
// lit: each lit cell's count of 400,000 picks within 5 standard deviations of N x windowPickPmf, no
// unlit cell picked, and the picks that find nothing within 5 standard deviations of N (1 - sum).
TEST(NightWindows, LitCellPickMatchesItsPmf) {
    for (const float share : {0.07f, 0.5f}) {
        const WallRecord w = testWall(12, 10, share, 321u);
        const uint32_t cells = w.slots * w.floors;
        uint32_t lit = 0;
        for (uint32_t f = 0; f < w.floors; ++f)
            for (uint32_t s = 0; s < w.slots; ++s) lit += cellLit(w, cellLayout(w, f, s));
        ASSERT_GT(lit, 2u);
        const double pmf = windowPickPmf(cells, lit);
        EXPECT_NEAR(pmf * lit, 1.0 - std::pow(1.0 - double(lit) / cells, windowPickTries(cells, lit)), 1e-5);
        const int n = 400000;
        std::vector<int> count(cells, 0);
        int missed = 0;
        std::mt19937 rng(17);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        for (int i = 0; i < n; ++i) {
            uint32_t floor, slot;
            if (windowPickCell(w, lit, unit(rng), floor, slot)) ++count[floor * w.slots + slot];
            else ++missed;
        }
        for (uint32_t f = 0; f < w.floors; ++f)
            for (uint32_t s = 0; s < w.slots; ++s) {
                const int c = count[f * w.slots + s];
                if (!cellLit(w, cellLayout(w, f, s))) {
                    EXPECT_EQ(c, 0) << "unlit cell " << f << ", " << s;
                    continue;
                }
                EXPECT_NEAR(c, n * pmf, 5.0 * std::sqrt(n * pmf)) << "share " << share << " cell " << f << ", " << s;
            }
        const double miss = 1.0 - pmf * lit;
        EXPECT_NEAR(missed, n * miss, 5.0 * std::sqrt(n * miss) + 1.0) << "share " << share;
    }
}

// The aggregate's sampler against its pdf (chi-square over directions about the way to the wall),
// and the pdf's integral: the chance that a pick finds a lit cell (windowPickPmf times the lit cells).
TEST(NightWindows, AggregateSamplerMatchesItsPdf) {
    const WallRecord w = testWall(4, 3, 0.5f, 77u);
    const std::vector<Material> materials = wallMaterials();
    Scene scene = nightScene(TriangleMesh{}, materials, {w}, {});
    buildLights(scene);
    const SceneView view = scene.view();
    ASSERT_EQ(scene.walls.size(), 1u);
    const LightRecord light = lightRecord(view, view.lights.first<WindowLight>());
    ASSERT_EQ(light.kind, kLightKindOf<WindowLight>);
    const Vec3f from{2.0f, 3.0f, 9.0f};
    chi2::DirectionBins bins;
    bins.frame = Frame::fromZ(normalize(w.worldFromWall(0.5f * w.width, 0.5f * w.height, 0) - from));
    bins.cosMin = 0.6;
    bins.subdivisions = 64;
    bins.smooth = false;
    const auto pdf = [&](Vec3f d) { return double(lightPdf(view, light, d, 0, 0, from)); };
    // The bins' expected counts are scaled to the samples (edges inside bins: chi2.h), so the
    // sampler is conditioned on a lit cell by rejection: a pick that finds none draws again.
    std::mt19937 retry(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const chi2::Outcome outcome = chi2::testDirections(
        [&](float u0, float u1, float u2, Vec3f& d) {
            LightSample s;
            for (float u = u0; !sampleLight(view, light, from, u, u1, u2, s); u = unit(retry)) {}
            d = s.dir;
            return true;
        },
        pdf, bins, 200000, 31);
    EXPECT_GT(outcome.pValue, chi2::sidakLevel(1)) << outcome.message;
    uint32_t lit = 0;
    for (uint32_t f = 0; f < w.floors; ++f)
        for (uint32_t s = 0; s < w.slots; ++s) lit += cellLit(w, cellLayout(w, f, s));
    ASSERT_GT(lit, 0u);
    ASSERT_LT(lit, w.floors * w.slots);
    ASSERT_EQ(light.litCells, lit);
    EXPECT_NEAR(chi2::integratePdf(pdf, bins), windowPickPmf(w.floors * w.slots, lit) * lit, 0.01);
}

// A small night scene: a plane before a wall of lit windows, the sun down, a black sky. MIS (light
// samples of the windows through their panes, BSDF samples weighed against them) and BSDF sampling
// alone (8 times the samples) converge to the same image: means within 2 %, each of 4 x 4 block
// means within 10 % (the blocks scattered by +-15 % with 1024 BSDF samples and by +-8 % with 8192,
// both ways: the BSDF-only reference's noise). Paths end by Russian roulette, not by a depth: a pane
// is one more vertex on the BSDF sample's way to a room than on the light sample's, so at a depth
// limit the two strategies would count different paths (at 3, blocks differed 2.85 times).
TEST(NightWindows, MisConvergesToBsdfSampling) {
    const WallRecord w = testWall(6, 4, 0.6f, 99u);
    TriangleMesh mesh;
    test::addSquare(mesh, 200.0f, 0.0f, 0);
    Scene scene = nightScene(mesh, wallMaterials(), {w}, {});
    buildLights(scene);
    ASSERT_NE(scene.lights.first<WindowLight>(), kNoLight);
    const Camera camera = cameraFromHeading(Vec3f{0.0f, 1.7f, 14.0f}, 0.0f, -20.0f, 60.0f, 1.0f);
    const auto render = [&](uint32_t lightSamples, uint32_t spp) {
        RenderSettings settings;
        settings.width = settings.height = 24;
        settings.spp = spp;
        settings.maxDepth = 64;   // Russian roulette ends paths: no truncation that a pane's extra vertex would tell apart
        settings.lightSamples = lightSamples;
        RenderCounters counters;
        return renderCpu(scene.view(), camera, settings, false, counters);
    };
    const LinearImage mis = render(1, 1024), bsdf = render(0, 8192);
    const float a = luminance(imageMean(mis)), b = luminance(imageMean(bsdf));
    ASSERT_GT(b, 0.0f);
    EXPECT_NEAR(a / b, 1.0f, 0.02f);
    for (int by = 0; by < 4; ++by)
        for (int bx = 0; bx < 4; ++bx) {
            double sa = 0, sb = 0;
            for (int y = by * 6; y < by * 6 + 6; ++y)
                for (int x = bx * 6; x < bx * 6 + 6; ++x) {
                    sa += luminance(mis.pixels[y * 24 + x]);
                    sb += luminance(bsdf.pixels[y * 24 + x]);
                }
            if (sb > 1e-3 * b * 36) {
                EXPECT_NEAR(sa / sb, 1.0, 0.10) << "block " << bx << ", " << by;
            }
        }
}
