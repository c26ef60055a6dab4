// The atmosphere (Hillaire 2020): its transmittance table against the analytic optical depth of an
// exponential atmosphere, its single-scattered sky against a brute-force integral, the sun reddening
// as it sets, night against day, the twilight glow, aerial perspective against a numerical integral,
// and the sky's importance table against its pdf (chi-square).
#include "chi2_support.h"
#include "lights/light.h"
#include "lights/light_build.h"
#include "lights/light_sampler.h"
#include "media/aerial_perspective.h"
#include "media/atmosphere_build.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

using namespace urbis;

namespace {

/// An empty scene under the atmosphere with the sun at `elevation` and `azimuth` degrees.
Scene atmosphereScene(float elevation, float azimuth = 150.0f, bool multipleScattering = true) {
    Scene scene = Scene::build({.materials = {Material{}}});
    scene.sun = makeSun(elevation, azimuth, 0.27f, Vec3f{3, 3, 3});
    scene.sky.model = SkyModel::Atmosphere;
    buildAtmosphere(scene, multipleScattering);
    return scene;
}

ArrayView<Vec3f> viewOf(const std::vector<Vec3f>& lut) { return {lut.data(), uint32_t(lut.size())}; }

/// Mean luminance of the sky over the upper hemisphere (a grid uniform in cos theta and phi).
double meanSkyLuminance(const Scene& scene) {
    const SceneView view = scene.view();
    double sum = 0;
    const int n = 64;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float cosTheta = (float(i) + 0.5f) / float(n), phi = 2.0f * kPi * (float(j) + 0.5f) / float(n);
            const float sinTheta = sqrtf(1.0f - cosTheta * cosTheta);
            sum += luminance(skyRadiance(view, Vec3f{sinTheta * cosf(phi), cosTheta, sinTheta * sinf(phi)}));
        }
    return sum / (n * n);
}

/// Transmittance by numerical integration (double, many steps) from radius r along mu to the top.
Vec3f bruteTransmittance(const Atmosphere& a, double r, double mu, int steps) {
    const double t = double(distanceToSphere(float(r), float(mu), a.topRadius, false));
    const double dt = t / steps;
    double depth[3] = {0, 0, 0};
    for (int k = 0; k < steps; ++k) {
        const double s = (k + 0.5) * dt;
        const double h = std::sqrt(r * r + s * s + 2.0 * r * mu * s) - a.bottomRadius;
        const Vec3f e = sampleMedium(a, float(h)).extinction;
        for (int c = 0; c < 3; ++c) depth[c] += double(e[c]) * dt;
    }
    return {float(std::exp(-depth[0])), float(std::exp(-depth[1])), float(std::exp(-depth[2]))};
}

} // namespace

// Without ozone the atmosphere is two exponential layers: straight up from height h the optical
// depth is sum sigma H (e^(-h/H) - e^(-(top - h)/H)) exactly; along zenith cosine mu from the ground
// it is that over mu to within the curvature's H / (2 R) (1 - mu^2) / mu^2 share (0.2 % at mu = 0.5).
TEST(Atmosphere, TransmittanceMatchesAnalyticOpticalDepth) {
    Atmosphere a;
    a.ozoneAbsorption = {0, 0, 0};
    const std::vector<Vec3f> lut = buildTransmittanceLut(a);
    const float top = a.topRadius - a.bottomRadius;
    const auto depth = [&](float h, float H, float sigma) { return sigma * H * (expf(-h / H) - expf(-top / H)); };
    const float mieExtinction = a.mieScattering + a.mieAbsorption;
    for (float h : {0.0f, 0.35f, 1.7f, 6.3f, 23.0f, 61.0f}) {
        for (float mu : {1.0f, 0.83f, 0.61f, 0.5f}) {
            const Vec3f got = transmittanceToTop(a, viewOf(lut), a.bottomRadius + h, mu);
            for (int c = 0; c < 3; ++c) {
                const float tau = (depth(h, a.rayleighScaleHeight, a.rayleighScattering[c]) +
                                   depth(h, a.mieScaleHeight, mieExtinction)) / mu;
                EXPECT_NEAR(got[c], expf(-tau), 0.01f * expf(-tau)) << "h " << h << " km, mu " << mu << ", channel " << c;
            }
        }
    }
    // With ozone, near the horizon and from above, against a numerical integral of the medium.
    const Atmosphere earth;
    const std::vector<Vec3f> earthLut = buildTransmittanceLut(earth);
    for (float h : {0.0f, 2.2f, 14.0f, 47.0f})
        for (float mu : {0.93f, 0.37f, 0.08f, -0.02f}) {
            const float r = earth.bottomRadius + h;
            if (rayMeetsGround(earth, r, mu)) continue;
            const Vec3f want = bruteTransmittance(earth, r, mu, 200000), got = transmittanceToTop(earth, viewOf(earthLut), r, mu);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], want[c], 0.01f * want[c] + 1e-4f) << "h " << h << " km, mu " << mu << ", channel " << c;
        }
}

// Single scattering (the table built without multiple scattering) against a brute-force integral:
// 4000 steps along the view ray, each with its own 1000-step integral of the transmittance towards
// the sun, in double. The table's 64 steps and bilinear look-up stay within 3 %.
TEST(Atmosphere, SingleScatteredSkyMatchesBruteForce) {
    for (float elevation : {40.0f, 8.0f}) {
        const Scene scene = atmosphereScene(elevation, 90.0f, false);
        const SceneView view = scene.view();
        const Atmosphere& a = scene.sky.atmosphere;
        const double r0 = skyViewRadius(a);
        for (Vec3f dir : {Vec3f{0, 1, 0}, normalize(Vec3f{1, 0.4f, 0}), normalize(Vec3f{-1, 0.1f, 0.3f}),
                          normalize(Vec3f{0.2f, 0.05f, -1}), normalize(Vec3f{0.7f, 0.5f, 0.5f})}) {
            const int steps = 4000;
            const double tMax = double(distanceToSphere(float(r0), dir.y, a.topRadius, false)), dt = tMax / steps;
            const float cosTheta = dot(dir, a.sunDirection);
            double sum[3] = {0, 0, 0}, depth[3] = {0, 0, 0};
            for (int k = 0; k < steps; ++k) {
                const double s = (k + 0.5) * dt;
                const double px = dir.x * s, py = r0 + dir.y * s, pz = dir.z * s;
                const double r = std::sqrt(px * px + py * py + pz * pz);
                const double mu = (px * a.sunDirection.x + py * a.sunDirection.y + pz * a.sunDirection.z) / r;
                const MediumSample m = sampleMedium(a, float(r - a.bottomRadius));
                const Vec3f sunT = rayMeetsGround(a, float(r), float(mu)) ? Vec3f{} : bruteTransmittance(a, r, mu, 1000);
                for (int c = 0; c < 3; ++c) {
                    depth[c] += 0.5 * double(m.extinction[c]) * dt;
                    const double source = double(m.rayleighScattering[c]) * rayleighPhase(cosTheta) +
                                          double(m.mieScattering) * miePhase(a.mieG, cosTheta);
                    sum[c] += std::exp(-depth[c]) * source * double(sunT[c]) * dt;
                    depth[c] += 0.5 * double(m.extinction[c]) * dt;
                }
            }
            const Vec3f got = skyRadiance(view, dir);
            for (int c = 0; c < 3; ++c) {
                const double want = sum[c] * double(a.solarIrradiance[c]);
                EXPECT_NEAR(double(got[c]), want, 0.03 * want)
                    << "sun " << elevation << " deg, dir " << dir.x << "," << dir.y << "," << dir.z << ", channel " << c;
            }
        }
    }
}

// The sun's radiance through the atmosphere: red over blue grows as it sets, and it is gone below the horizon.
TEST(Atmosphere, SunReddensAsItSets) {
    double previous = 0, high = 0;
    for (float elevation : {70.0f, 40.0f, 20.0f, 10.0f, 5.0f, 2.0f}) {
        const Vec3f sun = atmosphereScene(elevation).sun.radiance;
        const double ratio = double(sun.x) / double(sun.z);
        std::cout << "sun at " << elevation << " deg: radiance " << sun.x << " " << sun.y << " " << sun.z << ", R/B " << ratio << "\n";
        EXPECT_GT(ratio, previous) << "at " << elevation << " degrees";
        if (previous == 0) high = ratio;
        previous = ratio;
    }
    EXPECT_GT(previous, 3.0 * high) << "the low sun is far redder than the high one";
    EXPECT_FALSE(sunEnabled(atmosphereScene(-1.0f).sun)) << "below the horizon the sun gives no light";
}

// Night (the sun 18 degrees down: astronomical twilight ends) against day; the glow just after sunset
// lies on the horizon towards the sun.
TEST(Atmosphere, NightIsDarkAndTwilightGlowsTowardsTheSun) {
    const double day = meanSkyLuminance(atmosphereScene(40.0f));
    const double night = meanSkyLuminance(atmosphereScene(-18.0f));
    std::cout << "sky luminance: day " << day << ", night " << night << "\n";
    EXPECT_LT(night, 1e-3 * day);
    const Scene dusk = atmosphereScene(-4.0f, 270.0f);  // west
    const SceneView view = dusk.view();
    const double west = luminance(skyRadiance(view, normalize(Vec3f{-1, 0.03f, 0})));
    const double east = luminance(skyRadiance(view, normalize(Vec3f{1, 0.03f, 0})));
    const double zenith = luminance(skyRadiance(view, Vec3f{0, 1, 0}));
    std::cout << "dusk: west horizon " << west << ", east horizon " << east << ", zenith " << zenith << "\n";
    EXPECT_GT(west, 3.0 * east);
    EXPECT_GT(west, zenith);
    EXPECT_GT(west, 1e-3 * day) << "the glow is no night";
}

// A segment's in-scattering and transmittance (closed form per layer, the sun's transmittance and
// multiple scattering at its middle) against a numerical integral along it that takes both at every
// point: within 1 % over 6 km climbing 400 m.
TEST(Atmosphere, AerialPerspectiveMatchesNumericalIntegral) {
    const Scene scene = atmosphereScene(25.0f, 200.0f);
    const Atmosphere& a = scene.sky.atmosphere;
    const SceneView view = scene.view();
    for (Vec3f dir : {normalize(Vec3f{0.3f, 0.0667f, -1}), normalize(Vec3f{-1, -0.02f, 0.1f})}) {
        const Vec3f origin{0, 150, 0};
        const float distance = 6000.0f;
        const SegmentMedium m = atmosphereSegment(a, view.transmittanceLut, view.multiScatteringLut, origin, dir, distance);
        const int steps = 20000;
        const double dt = distance * 1e-3 / steps;
        double depth[3] = {0, 0, 0}, sum[3] = {0, 0, 0};
        const float cosTheta = dot(dir, a.sunDirection);
        for (int k = 0; k < steps; ++k) {
            const double h = a.altitude + (origin.y + dir.y * (k + 0.5) * dt * 1e3) * 1e-3;
            const float r = a.bottomRadius + float(h);
            const MediumSample s = sampleMedium(a, float(h));
            const Vec3f sunT = transmittanceToTop(a, view.transmittanceLut, r, a.sunDirection.y);
            const Vec3f psi = multiScattering(a, view.multiScatteringLut, r, a.sunDirection.y);
            for (int c = 0; c < 3; ++c) {
                depth[c] += 0.5 * double(s.extinction[c]) * dt;
                const double source = (double(s.rayleighScattering[c]) * rayleighPhase(cosTheta) +
                                       double(s.mieScattering) * miePhase(a.mieG, cosTheta)) * sunT[c] +
                                      (double(s.rayleighScattering[c]) + s.mieScattering) * psi[c];
                sum[c] += std::exp(-depth[c]) * source * dt * a.solarIrradiance[c];
                depth[c] += 0.5 * double(s.extinction[c]) * dt;
            }
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(m.transmittance[c], std::exp(-depth[c]), 1e-3 * std::exp(-depth[c])) << "channel " << c;
            EXPECT_NEAR(m.inScattered[c], sum[c], 0.01 * sum[c]) << "channel " << c;
        }
        std::cout << "6 km of haze: transmittance " << m.transmittance.x << " " << m.transmittance.y << " "
                  << m.transmittance.z << ", in-scattered " << m.inScattered.x << " " << m.inScattered.y << " "
                  << m.inScattered.z << "\n";
    }
}

// The atmosphere's sky as a light: directions from its importance table distributed as its pdf.
TEST(Atmosphere, SkyTableSamplesItsPdf) {
    Scene scene = atmosphereScene(30.0f);
    LightBuildOptions options;
    options.skyMinShare = 0.0f;
    buildLights(scene, options);
    const SceneView view = scene.view();
    ASSERT_NE(view.lights.first<SkyLight>(), kNoLight);
    const LightRecord sky = lightRecord(view, view.lights.first<SkyLight>());
    chi2::DirectionBins bins;
    bins.frame = Frame{Vec3f{1, 0, 0}, Vec3f{0, 0, 1}, Vec3f{0, 1, 0}};
    bins.smooth = false;
    bins.cosMin = -1.0;
    bins.thetaBins = 32;
    bins.phiBins = 32;
    bins.subdivisions = 12;
    const chi2::Outcome outcome = chi2::testDirections(
        [&](float u0, float u1, float u2, Vec3f& d) {
            LightSample s;
            if (!sampleLight(view, sky, Vec3f{}, u0, u1, u2, s)) return false;
            d = s.dir;
            return true;
        },
        [&](Vec3f d) { return double(lightPdf(view, sky, d, 0, 0)); }, bins, 400000, 21);
    EXPECT_GT(outcome.pValue, chi2::sidakLevel(1)) << outcome.message;
    // The table follows the sky: towards the sun's side of the horizon samples are likelier than at the zenith.
    const Vec3f towardsSun = normalize(Vec3f{scene.sun.direction.x, 0.3f, scene.sun.direction.z});
    EXPECT_GT(lightPdf(view, sky, towardsSun, 0, 0), lightPdf(view, sky, Vec3f{0, 1, 0}, 0, 0));
}

// A hand-built scene whose sky is the atmosphere but whose tables nobody built: buildLights builds
// them first (it used to read the empty tables and crash), and the result is that of the two steps
// in order, the sun dimmed by the atmosphere once.
TEST(Atmosphere, BuildLightsBuildsTheTablesItNeeds) {
    const auto scene = [](bool atmosphereFirst) {
        Scene s = Scene::build({.materials = {Material{}}});
        s.sun = makeSun(20.0f, 150.0f, 0.27f, Vec3f{3, 3, 3});
        s.sky.model = SkyModel::Atmosphere;
        if (atmosphereFirst) buildAtmosphere(s);
        buildLights(s);
        return s;
    };
    const Scene direct = scene(false), twoSteps = scene(true);
    ASSERT_FALSE(direct.skyViewLut.empty());
    EXPECT_EQ(direct.skyViewLut.size(), twoSteps.skyViewLut.size());
    EXPECT_FLOAT_EQ(direct.sun.radiance.x, twoSteps.sun.radiance.x);
    EXPECT_EQ(direct.lightRecords.size(), twoSteps.lightRecords.size());
    EXPECT_GT(luminance(skyRadiance(direct.view(), Vec3f{0, 1, 0})), 0.0f);
}

// A sequence relights its scene each frame: a scene lit at noon and then relit for dusk keeps its
// transmittance and multiple-scattering tables (they depend on the medium, not the sun) and ends with
// the bits of a scene lit for dusk alone; another medium builds them again.
TEST(Atmosphere, RelightingTheSameMediumKeepsTheSunFreeTables) {
    const auto sameBits = [](const std::vector<Vec3f>& a, const std::vector<Vec3f>& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3f)) == 0;
    };
    const Scene dusk = atmosphereScene(3.0f, 250.0f);
    Scene relit = atmosphereScene(60.0f);
    const Atmosphere noon = relit.sky.atmosphere;
    const Vec3f* kept = relit.multiScatteringLut.data();
    relit.sun = makeSun(3.0f, 250.0f, 0.27f, Vec3f{3, 3, 3});
    buildAtmosphere(relit, true, &noon);
    EXPECT_EQ(relit.multiScatteringLut.data(), kept) << "the multiple-scattering table was built again";
    EXPECT_TRUE(sameBits(relit.transmittanceLut, dusk.transmittanceLut));
    EXPECT_TRUE(sameBits(relit.multiScatteringLut, dusk.multiScatteringLut));
    EXPECT_TRUE(sameBits(relit.skyViewLut, dusk.skyViewLut));
    EXPECT_EQ(std::memcmp(&relit.sun, &dusk.sun, sizeof(Sun)), 0) << "the sun's transmittance differs";

    Scene hazy = atmosphereScene(60.0f);
    const Atmosphere clear = hazy.sky.atmosphere;
    hazy.sky.atmosphere.mieScattering *= 4.0f;
    hazy.sun = makeSun(3.0f, 250.0f, 0.27f, Vec3f{3, 3, 3});
    buildAtmosphere(hazy, true, &clear);
    EXPECT_FALSE(sameMedium(clear, hazy.sky.atmosphere));
    EXPECT_FALSE(sameBits(hazy.transmittanceLut, dusk.transmittanceLut)) << "another medium kept the old tables";
    EXPECT_TRUE(sameMedium(noon, dusk.sky.atmosphere));
}
