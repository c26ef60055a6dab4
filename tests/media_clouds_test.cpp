// Clouds: the tracking estimators against analytic transmittance and free-flight distributions, the
// phase function's normalisation and sampling, the density against its majorants, and the clouds'
// shadow on the ground.
#include "chi2_support.h"

#include "cpu/cpu_renderer.h"
#include "math/constants.h"
#include "math/hash.h"
#include "media/cloud_build.h"
#include "media/cloud_scattering.h"
#include "scene/camera_framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace urbis;

namespace {

/// A homogeneous slab (a Uniform layer) of extinction `sigma` per metre from `bottom` over `thickness` metres.
CloudLayer uniformSlab(float sigma, float bottom, float thickness, float albedo = 0.99f) {
    CloudLayer layer;
    layer.type = CloudType::Uniform;
    layer.coverage = 1.0f;
    layer.density = sigma;
    layer.bottom = bottom;
    layer.thickness = thickness;
    layer.albedo = albedo;
    return layer;
}

/// Mean and standard error of `n` draws of `estimate()`.
template <typename Estimate>
std::pair<double, double> meanAndError(uint32_t n, Estimate&& estimate) {
    double sum = 0, sum2 = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double x = estimate(i);
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

} // namespace

// Ratio tracking through the world's homogeneous slab (the layer, its cells and its majorants as the
// renderer walks them) against exp(-sigma d): the mean of 200,000 walks within 1 % and within four
// standard errors, straight up and at 60 degrees from the zenith, and through the slab's side.
TEST(Clouds, SlabTransmittanceIsBeerLambert) {
    Scene scene;
    buildClouds(scene, uniformSlab(0.002f, 1000.0f, 500.0f));
    const SceneView view = scene.view();
    ASSERT_TRUE(hasClouds(view));
    const float s60 = std::sin(60.0f * kPi / 180.0f), c60 = 0.5f;
    struct Case {
        Ray ray;
        double depth;  // optical
    } cases[] = {{Ray{Vec3f{10, 0, 20}, Vec3f{0, 1, 0}}, 1.0},
                 {Ray{Vec3f{-300, 0, 40}, Vec3f{s60, c60, 0} * 3.0f}, 2.0},   // t counts |dir|: any length
                 {Ray{Vec3f{0, 1200, 0}, Vec3f{0, 0, 1}, 0.0f, 600.0f}, 1.2}};
    for (const Case& c : cases) {
        const auto [mean, error] = meanAndError(200000, [&](uint32_t i) {
            SampleStream rng{1, i, 0};
            return cloudTransmittance(view, c.ray, CloudOctaves{}, rng);
        });
        const double expected = std::exp(-c.depth);
        EXPECT_NEAR(mean, expected, 0.01 * expected) << "optical depth " << c.depth << ", error " << error;
        EXPECT_NEAR(mean, expected, 4.0 * error) << "optical depth " << c.depth;
    }
}

// Ratio tracking under a majorant above the density (every step takes 1 - sigma / majorant) is
// unbiased: a constant medium at half its majorant, and a linear ramp sigma(t) = a t, whose
// transmittance is exp(-a d^2 / 2), and Wrenninge's octaves, which scale the extinction. The mean of
// 100,000 walks lies within four standard errors of the analytic answer (a false alarm 1 in 16,000).
TEST(Clouds, RatioTrackingIsUnbiased) {
    const float d = 800.0f, a = 3e-6f, sigma = 1.5e-3f;
    const auto constant = [&](float) { return sigma; };
    const auto ramp = [&](float t) { return a * t; };
    CloudOctaves octaves;
    octaves.count = 3;
    octaves.extinction[1] = 0.5f;
    octaves.extinction[2] = 0.25f;
    struct Case {
        const char* name;
        bool isRamp;
        float majorant;
        double depth;
    } cases[] = {{"constant", false, 2.0f * sigma, sigma * d}, {"ramp", true, 1.2f * a * d, 0.5 * a * d * d}};
    for (const Case& c : cases)
        for (uint32_t octave = 0; octave < 3; ++octave) {
            const auto [mean, error] = meanAndError(100000, [&](uint32_t i) {
                SampleStream rng{2 + octave, i, 0};
                float T[kCloudMaxOctaves] = {1, 1, 1, 1};
                if (c.isRamp) ratioTrack(ramp, c.majorant, 0.0f, d, octaves, T, rng);
                else ratioTrack(constant, c.majorant, 0.0f, d, octaves, T, rng);
                return double(T[octave]);
            });
            const double expected = std::exp(-c.depth * octaves.extinction[octave]);
            EXPECT_NEAR(mean, expected, 4.0 * error) << c.name << ", octave " << octave;
            EXPECT_LT(error, 0.01 * expected) << c.name << ": too few walks to tell";
        }
}

// Delta tracking's free-flight distances in a homogeneous medium at a third of its majorant follow
// the analytic exponential: chi-square over 40 bins of equal probability, 100,000 flights; the
// renderer's walk through the slab collides with probability 1 - exp(-tau).
TEST(Clouds, DeltaTrackingFollowsTheExponential) {
    const float sigma = 0.01f, majorant = 0.03f;
    const auto constant = [&](float) { return sigma; };
    constexpr int kBins = 40;
    std::vector<double> observed(kBins, 0.0), expected(kBins, 100000.0 / kBins);
    for (uint32_t i = 0; i < 100000; ++i) {
        SampleStream rng{5, i, 0};
        float t;
        ASSERT_TRUE(deltaTrack(constant, majorant, 0.0f, 3.0e38f, rng, t));
        const double cdf = 1.0 - std::exp(-double(sigma) * t);
        observed[std::min(kBins - 1, int(cdf * kBins))] += 1;
    }
    const chi2::Outcome outcome = chi2::pearson(observed, expected);
    EXPECT_GT(outcome.pValue, 0.001) << outcome.message;

    Scene scene;
    buildClouds(scene, uniformSlab(0.002f, 1000.0f, 500.0f));
    const SceneView view = scene.view();
    const auto [collided, error] = meanAndError(100000, [&](uint32_t i) {
        SampleStream rng{6, i, 0};
        float t;
        const Ray ray{Vec3f{0, 0, 0}, Vec3f{0, 1, 0}};
        const bool hit = cloudCollision(view, ray, 3.0e38f, rng, t);
        EXPECT_TRUE(!hit || (t > 1000.0f && t < 1500.0f)) << t;
        return hit ? 1.0 : 0.0;
    });
    EXPECT_NEAR(collided, 1.0 - std::exp(-1.0), 4.0 * error);
}

// The two-lobe phase function integrates to one over the sphere (midpoint rule, 20,000 steps in the
// cosine), for the default lobes and the flattened ones of the octaves; its sampling follows its
// value as pdf (chi-square over 20 x 8 bins of cosine and azimuth about the incoming direction).
TEST(Clouds, PhaseFunctionIsNormalisedAndSampled) {
    const CloudLayer layer;
    for (float scale : {1.0f, 0.5f, 0.25f, 0.0f}) {
        const CloudPhase phase = cloudPhase(layer, scale);
        double integral = 0;
        constexpr int kSteps = 20000;
        for (int i = 0; i < kSteps; ++i)
            integral += cloudPhaseValue(phase, -1.0f + (i + 0.5f) * 2.0f / kSteps) * (2.0 / kSteps) * 2.0 * kPi;
        EXPECT_NEAR(integral, 1.0, 1e-3) << "anisotropy scale " << scale;
    }
    const CloudPhase phase = cloudPhase(layer);
    const Vec3f in = normalize(Vec3f{0.3f, -0.8f, 0.5f});
    const Frame frame = Frame::fromZ(in);
    constexpr int kCos = 20, kPhi = 8, kSamples = 200000;
    std::vector<double> observed(kCos * kPhi, 0.0), expected(kCos * kPhi, 0.0);
    // The bins' cosine edges follow the forward lobe so that each holds a fair share.
    const auto cosEdge = [](int i) { return i == kCos ? 1.0 : -1.0 + 2.0 * std::pow(double(i) / kCos, 0.25); };
    for (int i = 0; i < kCos; ++i) {
        double p = 0;
        for (int k = 0; k < 400; ++k) {
            const double c = cosEdge(i) + (k + 0.5) / 400 * (cosEdge(i + 1) - cosEdge(i));
            p += cloudPhaseValue(phase, float(c)) * (cosEdge(i + 1) - cosEdge(i)) / 400 * 2.0 * kPi;
        }
        for (int j = 0; j < kPhi; ++j) expected[i * kPhi + j] = p / kPhi * kSamples;
    }
    for (uint32_t s = 0; s < kSamples; ++s) {
        SampleStream rng{7, s, 0};
        const float uLobe = rng.draw(), u1 = rng.draw(), u2 = rng.draw();
        const Vec3f out = sampleCloudPhase(phase, in, uLobe, u1, u2);
        ASSERT_NEAR(length(out), 1.0f, 1e-4f);
        const double c = dot(out, in);
        const double phi = std::atan2(dot(out, frame.y), dot(out, frame.x)) + kPi;
        int i = 0;
        while (i + 1 < kCos && c >= cosEdge(i + 1)) ++i;
        observed[i * kPhi + std::min(kPhi - 1, int(phi / (2.0 * kPi) * kPhi))] += 1;
    }
    const chi2::Outcome outcome = chi2::pearson(observed, expected);
    EXPECT_GT(outcome.pValue, 0.001) << outcome.message;
}

// The tracking is unbiased only if no density exceeds its cell's and band's majorant: 200,000 random
// points of cumulus layers of coverage 0.3, 0.7 and 1 and of a stratus layer of 0.7; and more
// coverage covers more of the cumulus layer's middle, none nothing.
TEST(Clouds, DensityStaysUnderItsMajorants) {
    double covered[3] = {};
    const float coverages[3] = {0.3f, 0.7f, 1.0f};
    for (CloudType type : {CloudType::Cumulus, CloudType::Stratus})
        for (int k = type == CloudType::Cumulus ? 0 : 1; k < (type == CloudType::Cumulus ? 3 : 2); ++k) {
            CloudLayer layer;
            layer.type = type;
            layer.coverage = coverages[k];
            layer.wind = Vec3f{1234.0f, 0.0f, -567.0f};
            Scene scene;
            buildClouds(scene, layer);
            const SceneView view = scene.view();
            const CloudLayer& built = view.cloudLayers[0];
            const CloudTables tables = cloudTables(view);
            HashStream rng{uint32_t(k) + 10u * uint32_t(type)};
            uint32_t inside = 0, clouded = 0;
            for (int i = 0; i < 200000; ++i) {
                const Vec3f p{(rng.uniform() - 0.5f) * 60000.0f, 1400.0f + rng.uniform() * 2700.0f, (rng.uniform() - 0.5f) * 60000.0f};
                const float density = cloudDensity(built, tables, p, p.y);
                const Vec3f q = p - built.wind;
                const float h = (p.y - built.bottom) / built.thickness;
                const float majorant = cloudMajorant(built, tables.majorants, int32_t(std::floor(q.x / built.coverageCell)),
                                                     int32_t(std::floor(q.z / built.coverageCell)),
                                                     int32_t(std::floor(h * kCloudBands)));
                ASSERT_LE(density, majorant) << "at " << p.x << ", " << p.y << ", " << p.z;
                ASSERT_GE(density, 0.0f);
                if (std::hypot(p.x, p.z) < 20000.0f && h > 0.3f && h < 0.5f) {
                    ++inside;
                    clouded += density > 0.0f;
                }
            }
            if (type == CloudType::Cumulus) covered[k] = double(clouded) / inside;
        }
    EXPECT_LT(covered[0], covered[1]);
    EXPECT_LT(covered[1], covered[2]);
    Scene clear;
    CloudLayer none;
    none.coverage = 0.0f;
    buildClouds(clear, none);
    EXPECT_FALSE(hasClouds(clear.view()));
    EXPECT_EQ(clear.memory().cloudNoise + clear.memory().cloudCoverage, 0u);
}

// The tables are the same for the same seed (the build is parallel), and differ for another.
TEST(Clouds, NoiseIsDeterministic) {
    const std::vector<CloudNoiseTexel> a = buildCloudNoise(3), b = buildCloudNoise(3), c = buildCloudNoise(4);
    ASSERT_EQ(a.size(), size_t(kCloudNoiseSize) * kCloudNoiseSize * kCloudNoiseSize);
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(CloudNoiseTexel)));
    EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(CloudNoiseTexel)));
}

namespace {

constexpr float kSunElevation = 35.0f, kSunAzimuth = 120.0f;

/// A 400 m Lambertian plane (albedo 0.5) about `centre` under a black sky and a sun at 35 degrees,
/// beneath `layer` (none where its coverage is 0).
Scene groundScene(const CloudLayer& layer, Vec3f centre) {
    TriangleMesh mesh;
    const float h = 200.0f;
    const Vec3f a = centre + Vec3f{-h, 0, -h}, b = centre + Vec3f{h, 0, -h}, c = centre + Vec3f{h, 0, h},
                d = centre + Vec3f{-h, 0, h};
    mesh.add({a, d, c}, {0, 0});
    mesh.add({a, c, b}, {0, 0});
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{Vec3f{0.5f, 0.5f, 0.5f}}}});
    scene.sky = Sky::uniform(Vec3f{});
    scene.sun = makeSun(kSunElevation, kSunAzimuth, 0.27f, Vec3f{3.0f, 3.0f, 3.0f});
    buildClouds(scene, layer);
    return scene;
}

/// The mean luminance of a 32 x 24 view of the plane of groundScene from 10 m above `centre`.
double meanGroundRadiance(const CloudLayer& layer, Vec3f centre, uint32_t spp) {
    const Scene scene = groundScene(layer, centre);
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    settings.spp = spp;
    const Camera camera = cameraFromHeading(centre + Vec3f{0, 10, 0}, 200.0f, -50.0f, 40.0f, 32.0f / 24.0f);
    RenderCounters counters;
    const LinearImage image = renderCpu(scene.view(), camera, settings, false, counters);
    double sum = 0;
    for (const Vec3f& p : image.pixels) sum += luminance(p);
    return sum / double(image.pixels.size());
}

} // namespace

// Clouds darken the ground in their shadow: under a purely absorbing homogeneous slab of optical
// depth 0.6 straight up, the sunlit plane keeps exp(-0.6 / sin 35 deg) = 0.351 of its radiance (the
// mean of 49,152 binary shadow estimates, whose standard error is 0.0022: within 0.01). Under cumulus
// of coverage 0.5, where the clouds' mean transmittance towards the sun is below 0.2 (the first such
// point along a line of the ground), the ground keeps less than 0.6 of its clear radiance though the
// clouds scatter light down to it; where it is above 0.8, more than 0.8.
TEST(Clouds, CloudsDarkenTheGroundInTheirShadow) {
    CloudLayer none;
    none.coverage = 0.0f;
    const double clear = meanGroundRadiance(none, Vec3f{}, 64);
    ASSERT_GT(clear, 0.1);
    const double slab = meanGroundRadiance(uniformSlab(0.002f, 1000.0f, 300.0f, 0.0f), Vec3f{}, 64);
    const double expected = std::exp(-0.6 / std::sin(kSunElevation * kPi / 180.0));
    EXPECT_NEAR(slab / clear, expected, 0.01) << "ratio " << slab / clear;

    CloudLayer cumulus;
    cumulus.coverage = 0.5f;
    const Scene probe = groundScene(cumulus, Vec3f{});
    const SceneView view = probe.view();
    const Vec3f toSun = probe.sun.direction;
    Vec3f shadowed{}, lit{};
    bool foundShadow = false, foundLight = false;
    for (int i = 0; i < 400 && !(foundShadow && foundLight); ++i) {
        const Vec3f p{-10000.0f + 50.0f * float(i), 0.0f, -5000.0f + 25.0f * float(i)};
        const auto [T, error] = meanAndError(64, [&](uint32_t k) {
            SampleStream rng{9, uint32_t(i), k};
            return cloudTransmittance(view, Ray{p, toSun}, CloudOctaves{}, rng);
        });
        if (!foundShadow && T < 0.2) shadowed = p, foundShadow = true;
        if (!foundLight && T > 0.8) lit = p, foundLight = true;
    }
    ASSERT_TRUE(foundShadow && foundLight) << "shadow " << foundShadow << ", gap " << foundLight << " along 22 km of ground";
    const double inShadow = meanGroundRadiance(cumulus, shadowed, 16), inGap = meanGroundRadiance(cumulus, lit, 16);
    EXPECT_LT(inShadow, 0.6 * clear) << "clear " << clear << ", in the shadow " << inShadow;
    EXPECT_GT(inGap, 0.8 * clear) << "clear " << clear << ", in a gap " << inGap;
}
