// The materials facades need, each checked where the answer is known: white furnaces for glass and
// the mirror (a lossless pane or mirror under a uniform sky is invisible), and for the glossy
// lobe a chi-square test of its sampler against its pdf plus the agreement of f * cos / pdf with
// the directional albedo integrated by quadrature.
#include "cpu/cpu_renderer.h"
#include "integrators/bsdf.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

using namespace urbis;

namespace {

/// A 400 m horizontal square of `material` under a uniform sky, seen from above at 60 degrees.
LinearImage furnace(const Material& material, Vec3f sky) {
    TriangleMesh mesh;
    const float h = 200.0f;
    mesh.add({{-h, 0, -h}, {-h, 0, h}, {h, 0, h}}, {});
    mesh.add({{-h, 0, -h}, {h, 0, h}, {h, 0, -h}}, {});
    Scene scene = Scene::build({.mesh = mesh, .materials = {material}});
    scene.sky = Sky::uniform(sky);
    RenderSettings s;
    s.width = 24;
    s.height = 16;
    s.spp = 64;
    Camera camera = cameraFromHeading(Vec3f{0, 10, 0}, 30.0f, -60.0f, 40.0f, 1.5f);
    RenderCounters counters;
    return renderCpu(scene.view(), camera, s, false, counters);
}

void expectEveryPixel(const LinearImage& image, Vec3f expected, float tolerance) {
    for (const Vec3f& p : image.pixels)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], expected[c], tolerance * expected[c]);
}

} // namespace

// A clear pane (no tint) reflects F and transmits 1 - F: under a uniform sky it is invisible.
TEST(FacadeMaterial, ClearGlassFurnace) {
    Material glass{Vec3f{1, 1, 1}, MaterialKind::Glass};
    expectEveryPixel(furnace(glass, Vec3f{0.7f, 1.0f, 1.3f}), Vec3f{0.7f, 1.0f, 1.3f}, 1e-4f);
}

// A tinted pane: the sky through it is tinted by the transmitted share, reflection is not:
// L * (F + (1 - F) * tint) per pixel, whose mean lies between tint * L and L.
TEST(FacadeMaterial, TintedGlassLiesBetweenTintAndClear) {
    Material glass{Vec3f{0.5f, 0.5f, 0.5f}, MaterialKind::Glass};
    const LinearImage image = furnace(glass, Vec3f{1, 1, 1});
    double mean = 0;
    for (const Vec3f& p : image.pixels) {
        EXPECT_GE(p.x, 0.5f);
        EXPECT_LT(p.x, 0.75f);   // Schlick at <= 60 degrees from the normal: F < 0.1
        mean += p.x / double(image.pixels.size());
    }
    EXPECT_GT(mean, 0.51) << "some light must be reflected (F is about 0.04 here)";
}

// A perfect mirror under a uniform sky shows the sky.
TEST(FacadeMaterial, MirrorFurnace) {
    Material mirror{Vec3f{1, 1, 1}, MaterialKind::Mirror};
    expectEveryPixel(furnace(mirror, Vec3f{0.4f, 0.5f, 0.6f}), Vec3f{0.4f, 0.5f, 0.6f}, 1e-4f);
}

// Emission is seen directly, added to what the surface reflects.
TEST(FacadeMaterial, EmissionAddsRadiance) {
    Material lit{Vec3f{0.5f, 0.5f, 0.5f}};
    lit.emission = Vec3f{2.0f, 1.0f, 0.5f};
    expectEveryPixel(furnace(lit, Vec3f{1, 1, 1}), Vec3f{2.5f, 1.5f, 1.0f}, 0.02f);
}

// Chi-square of the glossy sampler against bsdfPdf, over a grid of (theta, phi) bins about the
// normal, for a few exponents and viewing angles.
TEST(FacadeMaterial, GlossySamplerMatchesItsPdf) {
    const Vec3f n{0, 0, 1};
    for (float exponent : {5.0f, 40.0f, 300.0f})
        for (float viewDeg : {0.0f, 45.0f, 80.0f}) {
            Material m{Vec3f{0.3f, 0.3f, 0.3f}, MaterialKind::Glossy, Vec3f{0.6f, 0.6f, 0.6f}, exponent};
            const float a = viewDeg * kPi / 180.0f;
            const Vec3f wo{sinf(a), 0, cosf(a)};
            constexpr int kTheta = 32, kPhi = 32, kSamples = 400000;
            constexpr float kHalfPi = 0.5f * kPi;
            std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
            std::mt19937 rng(7);
            std::uniform_real_distribution<float> u(0.0f, 1.0f);
            int below = 0;
            for (int k = 0; k < kSamples; ++k) {
                BsdfSample s;
                if (!sampleBsdf(m, wo, n, u(rng), u(rng), u(rng), s)) {
                    ++below;
                    continue;
                }
                const float theta = acosf(fminf(1.0f, s.dir.z)), phi = atan2f(s.dir.y, s.dir.x) + kPi;
                const int i = std::min(kTheta - 1, int(theta / kHalfPi * kTheta)), j = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
                observed[i * kPhi + j] += 1.0;
            }
            // Expected counts: pdf * sin(theta) integrated over each bin (midpoint rule, 12 x 12 sub-grid).
            constexpr int kSub = 12;
            for (int i = 0; i < kTheta; ++i)
                for (int j = 0; j < kPhi; ++j) {
                    double sum = 0;
                    for (int si = 0; si < kSub; ++si)
                        for (int sj = 0; sj < kSub; ++sj) {
                            const float theta = (i + (si + 0.5f) / kSub) / kTheta * kHalfPi;
                            const float phi = (j + (sj + 0.5f) / kSub) / kPhi * 2 * kPi - kPi;
                            const Vec3f wi{sinf(theta) * cosf(phi), sinf(theta) * sinf(phi), cosf(theta)};
                            sum += bsdfPdf(m, wo, wi, n) * sinf(theta);
                        }
                    expected[i * kPhi + j] = sum / (kSub * kSub) * (kHalfPi / kTheta) * (2 * kPi / kPhi) * kSamples;
                }
            // Pool bins with fewer than 5 expected samples, then chi-square.
            double chi2 = 0, pooledObs = below, pooledExp = 0;
            int dof = 0;
            for (size_t b = 0; b < observed.size(); ++b) {
                if (expected[b] < 5) {
                    pooledObs += observed[b];
                    pooledExp += expected[b];
                    continue;
                }
                chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
                ++dof;
            }
            pooledExp = kSamples - std::accumulate(expected.begin(), expected.end(), 0.0) + pooledExp;
            if (pooledExp > 5) {
                chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
                ++dof;
            }
            // Wilson-Hilferty 1e-4 quantile: chi2 < dof * (1 + 3.72 * sqrt(2 / (9 dof)))^3 roughly.
            const double limit = dof * std::pow(1 + 3.72 * std::sqrt(2.0 / (9 * dof)), 3);
            EXPECT_LT(chi2, limit) << "exponent " << exponent << ", view " << viewDeg << " deg, dof " << dof;
        }
}

// The mean of sampleBsdf's weight is the directional albedo, which quadrature of evalBsdfCos gives
// independently; and it never exceeds 1 (energy conservation of the normalised lobe).
TEST(FacadeMaterial, GlossyWeightsIntegrateToTheAlbedo) {
    const Vec3f n{0, 0, 1};
    for (float exponent : {2.0f, 30.0f, 500.0f})
        for (float viewDeg : {10.0f, 60.0f}) {
            Material m{Vec3f{0.2f, 0.2f, 0.2f}, MaterialKind::Glossy, Vec3f{0.7f, 0.7f, 0.7f}, exponent};
            const float a = viewDeg * kPi / 180.0f;
            const Vec3f wo{sinf(a), 0, cosf(a)};
            std::mt19937 rng(11);
            std::uniform_real_distribution<float> u(0.0f, 1.0f);
            double mc = 0;
            constexpr int kSamples = 400000;
            for (int k = 0; k < kSamples; ++k) {
                BsdfSample s;
                if (sampleBsdf(m, wo, n, u(rng), u(rng), u(rng), s)) mc += s.weight.x;
            }
            mc /= kSamples;
            double quad = 0;
            constexpr int kT = 800, kP = 400;
            for (int i = 0; i < kT; ++i)
                for (int j = 0; j < kP; ++j) {
                    const float c = (i + 0.5f) / kT, phi = (j + 0.5f) / kP * 2 * kPi, st = sqrtf(1 - c * c);
                    quad += evalBsdfCos(m, wo, Vec3f{st * cosf(phi), st * sinf(phi), c}, n).x;
                }
            quad *= (1.0 / kT) * (2 * kPi / kP);
            EXPECT_NEAR(mc, quad, 0.01 * quad) << "exponent " << exponent << ", view " << viewDeg;
            EXPECT_LE(mc, 1.0);
        }
}
