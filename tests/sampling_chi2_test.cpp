// Every direction sampler of math/sampling.h and integrators/bsdf.h against its pdf: Pearson's
// chi-square test (tests/chi2_support.h) at a 1 % family-wise level, and the pdf's integral.
#include "chi2_support.h"
#include "integrators/bsdf.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

constexpr int kTests = 9;  // chi-square tests in this file, for the Sidak correction
constexpr uint32_t kSamples = 400000;

void expectFits(const chi2::DirectionSampler& sample, const chi2::DirectionPdf& pdf, const chi2::DirectionBins& bins,
                uint32_t seed) {
    const chi2::Outcome outcome = chi2::testDirections(sample, pdf, bins, kSamples, seed);
    EXPECT_GT(outcome.pValue, chi2::sidakLevel(kTests)) << outcome.message;
}

Material glossy(float exponent) {
    Material m;
    m.kind = MaterialKind::Glossy;
    m.albedo = Vec3f{0.3f, 0.35f, 0.4f};
    m.specular = Vec3f{0.4f, 0.4f, 0.4f};
    m.exponent = exponent;
    return m;
}

} // namespace

TEST(SamplingChi2, CosineHemisphere) {
    chi2::DirectionBins bins;
    bins.cosMin = 0;
    expectFits([](float, float u1, float u2, Vec3f& d) { return d = sampleCosineHemisphere(u1, u2), true; },
               [](Vec3f d) { return double(cosineHemispherePdf(d.z)); }, bins, 1);
}

// The test itself: a sampler tested against another's pdf fails.
TEST(SamplingChi2, RejectsAWrongPdf) {
    chi2::DirectionBins bins;
    bins.cosMin = 0;
    const chi2::Outcome outcome = chi2::testDirections(
        [](float, float u1, float u2, Vec3f& d) { return d = sampleCosineHemisphere(u1, u2), true; },
        [](Vec3f d) { return double(phongLobePdf(d.z, 1.3f)); }, bins, kSamples, 30);
    EXPECT_LT(outcome.pValue, 1e-6) << outcome.message;
}

TEST(SamplingChi2, UniformCone) {
    chi2::DirectionBins bins;
    bins.cosMin = 0.8;
    bins.smooth = false;  // the pdf's edge is the domain's
    expectFits([](float, float u1, float u2, Vec3f& d) { return d = sampleUniformCone(u1, u2, 0.8f), true; },
               [](Vec3f d) { return d.z >= 0.8f ? double(uniformConePdf(0.8f)) : 0.0; }, bins, 2);
}

TEST(SamplingChi2, UniformSphere) {
    chi2::DirectionBins bins;
    expectFits([](float, float u1, float u2, Vec3f& d) { return d = sampleUniformSphere(u1, u2), true; },
               [](Vec3f) { return double(uniformSpherePdf()); }, bins, 3);
}

TEST(SamplingChi2, PhongLobe) {
    for (float exponent : {1.0f, 12.0f, 80.0f}) {
        SCOPED_TRACE(exponent);
        chi2::DirectionBins bins;
        bins.cosMin = exponent > 50 ? 0.9 : 0.0;
        expectFits([&](float, float u1, float u2, Vec3f& d) { return d = samplePhongLobe(u1, u2, exponent), true; },
                   [&](Vec3f d) { return double(phongLobePdf(d.z, exponent)); }, bins, 4 + uint32_t(exponent));
    }
}

// The glossy mixture about a tilted wo: the lobe reaches below the surface, where sampleBsdf gives
// no sample; the outside bin expects exactly what the pdf leaves out.
TEST(SamplingChi2, GlossyBsdfMixture) {
    for (float exponent : {4.0f, 30.0f}) {
        const Material m = glossy(exponent);
        const Vec3f n{0, 0, 1}, wo = normalize(Vec3f{0.8f, 0.1f, 0.45f});
        chi2::DirectionBins bins;
        bins.cosMin = 0;
        expectFits(
            [&](float u0, float u1, float u2, Vec3f& d) {
                BsdfSample s;
                if (!sampleBsdf(m, wo, n, u0, u1, u2, s)) return false;
                EXPECT_NEAR(s.pdf, bsdfPdf(m, wo, s.dir, n), 1e-4f * s.pdf);
                d = s.dir;
                return true;
            },
            [&](Vec3f d) { return double(bsdfPdf(m, wo, d, n)); }, bins, 100 + uint32_t(exponent));
    }
}

TEST(SamplingChi2, LambertianBsdf) {
    Material m;
    const Vec3f n = normalize(Vec3f{0.3f, -0.5f, 0.8f}), wo = normalize(Vec3f{0.1f, 0.2f, 0.9f});
    chi2::DirectionBins bins;
    bins.frame = Frame::fromZ(n);
    bins.cosMin = 0;
    expectFits(
        [&](float u0, float u1, float u2, Vec3f& d) {
            BsdfSample s;
            if (!sampleBsdf(m, wo, n, u0, u1, u2, s)) return false;
            EXPECT_NEAR(s.pdf, bsdfPdf(m, wo, s.dir, n), 1e-4f);
            d = s.dir;
            return true;
        },
        [&](Vec3f d) { return double(bsdfPdf(m, wo, d, n)); }, bins, 200);
}

// Each pdf integrates to one over its domain (the glossy mixture: to its share above the surface).
TEST(SamplingPdf, IntegratesToOne) {
    chi2::DirectionBins hemisphere, sphere, cone;
    hemisphere.cosMin = 0;
    cone.cosMin = 0.95;
    hemisphere.subdivisions = sphere.subdivisions = cone.subdivisions = 24;
    EXPECT_NEAR(chi2::integratePdf([](Vec3f d) { return double(cosineHemispherePdf(d.z)); }, hemisphere), 1.0, 1e-3);
    EXPECT_NEAR(chi2::integratePdf([](Vec3f d) { return d.z >= 0.95f ? double(uniformConePdf(0.95f)) : 0.0; }, cone), 1.0, 1e-3);
    EXPECT_NEAR(chi2::integratePdf([](Vec3f) { return double(uniformSpherePdf()); }, sphere), 1.0, 1e-4);
    for (float exponent : {1.0f, 12.0f})
        EXPECT_NEAR(chi2::integratePdf([&](Vec3f d) { return double(phongLobePdf(d.z, exponent)); }, hemisphere), 1.0, 2e-3);
    const Material m = glossy(4.0f);
    const Vec3f n{0, 0, 1}, wo = normalize(Vec3f{0.8f, 0.1f, 0.45f});
    const double above = chi2::integratePdf([&](Vec3f d) { return double(bsdfPdf(m, wo, d, n)); }, hemisphere);
    EXPECT_LT(above, 1.0);
    EXPECT_GT(above, 0.8);
    // ... and that share is how often sampleBsdf returns a direction.
    SampleStream rng{7, 0, 0};
    uint32_t returned = 0, draws = 200000;
    for (uint32_t i = 0; i < draws; ++i) {
        BsdfSample s;
        returned += sampleBsdf(m, wo, n, rng.draw(), rng.draw(), rng.draw(), s);
    }
    EXPECT_NEAR(double(returned) / draws, above, 4e-3);
}
