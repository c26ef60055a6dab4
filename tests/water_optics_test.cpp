// The water's surface: the exact Fresnel reflectance against the textbook's angle form, energy
// (reflectance + transmittance = 1 from the amplitude coefficients, and the sampler's split), Snell's
// law, and the waves' slopes against the Cox-Munk variance they are built to.
#include "integrators/bsdf.h"
#include "integrators/water.h"
#include "math/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

/// Fresnel's equations in their angle form (Born and Wolf 1.5.2, eq. 35), in double: an independent
/// writing of the reflectance from the incidence angle and Snell's refraction angle.
double textbookReflectance(double thetaI, double n1, double n2) {
    const double sinT = n1 / n2 * std::sin(thetaI);
    if (sinT >= 1.0) return 1.0;
    const double thetaT = std::asin(sinT);
    if (thetaI == 0.0) return std::pow((n1 - n2) / (n1 + n2), 2);
    const double rs = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
    const double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
    return 0.5 * (rs * rs + rp * rp);
}

constexpr double kWater = 1.33;

} // namespace

// Both are given the same float cosine. Tolerance 2e-6 (float arithmetic on values of order 1),
// and 1e-4 within 2 degrees of the critical angle, where cos(theta_t) = sqrt(1 - sin^2) cancels.
TEST(WaterOptics, FresnelMatchesTheExactDielectricFormulaBothWays) {
    const double critical = std::asin(1.0 / kWater);
    for (int i = 0; i <= 900; ++i) {
        const float cosine = float(std::cos(i * (0.5 * M_PI / 900.0) * 0.9999));
        const double theta = std::acos(double(cosine));
        float cosT;
        const float fromAir = fresnelDielectric(cosine, float(kWater), cosT);
        EXPECT_NEAR(fromAir, textbookReflectance(theta, 1.0, kWater), 2e-6) << "air to water at " << theta;
        const float fromWater = fresnelDielectric(cosine, float(1.0 / kWater), cosT);
        const double tolerance = std::fabs(theta - critical) < 2.0 * M_PI / 180.0 ? 1e-4 : 2e-6;
        EXPECT_NEAR(fromWater, textbookReflectance(theta, kWater, 1.0), tolerance) << "water to air at " << theta;
    }
    float cosT;
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.33f, cosT), 0.33 * 0.33 / (2.33 * 2.33), 1e-7) << "normal incidence";
    // Total internal reflection beyond the critical angle asin(1 / 1.33) = 48.75 degrees.
    EXPECT_EQ(fresnelDielectric(float(std::cos(49.0 * M_PI / 180.0)), 1.0f / 1.33f, cosT), 1.0f);
    EXPECT_LT(fresnelDielectric(float(std::cos(48.5 * M_PI / 180.0)), 1.0f / 1.33f, cosT), 1.0f);
}

// Energy: the transmittance from Fresnel's amplitude transmission coefficients, t^2 n2 cos(theta_t) /
// (n1 cos(theta_i)) per polarisation, adds to the reflectance to 1 (within 1e-5, float).
TEST(WaterOptics, ReflectanceAndTransmittanceSumToOne) {
    for (const float eta : {1.33f, 1.0f / 1.33f})
        for (int i = 0; i < 90; ++i) {
            const float cosI = std::cos(float(i) * float(M_PI) / 180.0f);
            float cosT;
            const float r = fresnelDielectric(cosI, eta, cosT);
            if (cosT == 0.0f) continue;   // total internal reflection: r is 1, nothing is transmitted
            const float ts = 2.0f * cosI / (cosI + eta * cosT), tp = 2.0f * cosI / (eta * cosI + cosT);
            const float t = 0.5f * (ts * ts + tp * tp) * eta * cosT / cosI;
            EXPECT_NEAR(r + t, 1.0f, 1e-5f) << "eta " << eta << ", angle " << i;
        }
}

// The sampler reflects with the Fresnel probability (stratified u0: exactly, to the strata's 1e-4),
// refracts by Snell's law into the other side, and weighs each branch as the interface's radiance
// transfer: 1 reflected, 1 / eta^2 transmitted.
TEST(WaterOptics, SamplerSplitsByFresnelAndRefractsBySnell) {
    Material water{Vec3f{1, 1, 1}, MaterialKind::Water};
    water.ior = 1.33f;
    for (const float up : {1.0f, -1.0f})
        for (const float degrees : {0.0f, 20.0f, 45.0f, 70.0f, 85.0f}) {
            const float a = degrees * float(M_PI) / 180.0f;
            const Vec3f n{0, up, 0}, wo{std::sin(a), up * std::cos(a), 0};
            const float eta = up > 0 ? 1.33f : 1.0f / 1.33f;
            float cosT;
            const float expected = fresnelDielectric(std::cos(a), eta, cosT);
            constexpr int kStrata = 10000;
            int reflected = 0;
            for (int k = 0; k < kStrata; ++k) {
                BsdfSample s;
                ASSERT_TRUE(sampleBsdf(water, wo, n, (float(k) + 0.5f) / kStrata, 0.5f, 0.5f, s));
                ASSERT_TRUE(s.specular);
                EXPECT_NEAR(length(s.dir), 1.0f, 1e-5f);
                if (dot(s.dir, n) > 0.0f) {
                    ++reflected;
                    EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
                } else {
                    // Snell: n1 sin(i) = n2 sin(t), in the plane of incidence, on the other side.
                    const float sinT = std::sqrt(s.dir.x * s.dir.x + s.dir.z * s.dir.z);
                    EXPECT_NEAR(sinT * eta, std::sin(a), 1e-5f);
                    EXPECT_LE(s.dir.x * wo.x, 0.0f) << "refraction goes on across the normal";
                    EXPECT_NEAR(s.weight.y, 1.0f / (eta * eta), 1e-6f);
                }
            }
            EXPECT_NEAR(double(reflected) / kStrata, expected, 1e-4) << "up " << up << ", " << degrees << " degrees";
        }
}

// Over a 400 m square (far more than the longest wave), the mean-square slope of the normals is the
// Cox-Munk variance within 15 % (the Gerstner steepness and the normalisation bend it a little);
// a calm water is flat; every normal is unit and points up.
TEST(WaterOptics, WaveSlopesFollowTheWind) {
    for (const float speed : {2.0f, 5.0f, 10.0f}) {
        WaterOptics optics;
        optics.windX = speed * 0.6f;
        optics.windZ = -speed * 0.8f;
        double sum = 0;
        int count = 0;
        for (float x = -200.0f; x < 200.0f; x += 0.37f)
            for (float z = -200.0f; z < 200.0f; z += 5.3f) {
                const Vec3f n = waveNormal(optics, x + 3000.0f, z - 2000.0f);
                ASSERT_NEAR(length(n), 1.0f, 1e-5f);
                ASSERT_GT(n.y, 0.5f);
                sum += double(n.x * n.x + n.z * n.z) / double(n.y * n.y);
                ++count;
            }
        EXPECT_NEAR(sum / count / waterSlopeVariance(speed), 1.0, 0.15) << speed << " m/s";
    }
    const Vec3f calm = waveNormal(WaterOptics{}, 10.0f, 20.0f);
    EXPECT_EQ(calm.y, 1.0f);
}

TEST(WaterOptics, AbsorptionFollowsBeerLambertBelowTheSurfaceOnly) {
    Material water{Vec3f{1, 1, 1}, MaterialKind::Water};
    water.water.absorption = {0.5f, 0.1f, 0.05f};
    water.water.skipBelow = 0.08f;
    WaterPath path;
    EXPECT_EQ(path.transmittance(100.0f).x, 1.0f) << "in the air";
    BsdfSample down{normalize(Vec3f{0.3f, -1.0f, 0}), Vec3f{1, 1, 1}, true};
    const float tmin = path.scattered(water, Vec3f{0, 1, 0}, Vec3f{0, 1, 0}, down);
    EXPECT_NEAR(tmin * -down.dir.y, 0.08f, 1e-6f) << "the refracted ray starts below the flat ground's layer";
    EXPECT_NEAR(path.transmittance(2.0f).x, std::exp(-1.0f), 1e-6f);
    EXPECT_NEAR(path.transmittance(2.0f).z, std::exp(-0.1f), 1e-6f);
    BsdfSample up{normalize(Vec3f{0.3f, 1.0f, 0}), Vec3f{1, 1, 1}, true};
    path.scattered(water, Vec3f{0, -1, 0}, Vec3f{0, -1, 0}, up);
    EXPECT_EQ(path.transmittance(2.0f).x, 1.0f) << "out in the air again";
}
