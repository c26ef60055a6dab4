// The procedural stars (lights/star_field.h): the equal-area map, the count and total irradiance
// of the stars against the magnitude distribution they are drawn from, each star's radiance against
// its irradiance, and their turn with the sidereal time and the latitude (scene/night_sky.h).
#include "lights/star_field.h"
#include "math/sampling.h"
#include "scene/night_sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace urbis {
namespace {

// Equal areas of the map are equal solid angles: uniform directions fall evenly into 16 x 16 blocks
// of the map (chi-square with 255 degrees of freedom; 330 is its 0.1 % quantile).
TEST(Stars, MapIsEqualArea) {
    constexpr int kBlocks = 16, kSamples = 256 * 1000;
    std::vector<int> counts(kBlocks * kBlocks, 0);
    for (int i = 0; i < kSamples; ++i) {
        const Vec3f d = sampleUniformSphere(hashToUnit(hash2(1, uint32_t(i))), hashToUnit(hash2(2, uint32_t(i))));
        const Vec2f uv = equalAreaSquareFromSphere(d);
        ASSERT_TRUE(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f);
        ++counts[std::min(kBlocks - 1, int(uv.y * kBlocks)) * kBlocks + std::min(kBlocks - 1, int(uv.x * kBlocks))];
    }
    const double expected = double(kSamples) / (kBlocks * kBlocks);
    double chi2 = 0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 330.0);
}

// Every star of the sky, cell by cell: their number and their summed irradiance against the
// distribution's. With A = 10^(m / 2) uniform on [A(-1.5), A(6.5)], the mean of 10^(-0.4 m) is
// 5 (10^(0.1 m1) - 10^(0.1 m0)) / (A1 - A0). The hash draws one sky; its total has a relative
// standard deviation of about 5 % (the variance of 10^(-0.4 m) over the count), so 3 sigma is allowed.
TEST(Stars, TotalIrradianceFollowsTheMagnitudeDistribution) {
    double count = 0, total = 0;
    std::vector<double> brighterThan(9, 0.0);  // magnitudes -1 .. 7, by whole magnitude
    for (uint32_t cy = 0; cy < kStarMapSide; ++cy)
        for (uint32_t cx = 0; cx < kStarMapSide; ++cx) {
            const Star star = starInCell(cx, cy);
            if (!star.present) continue;
            count += 1;
            total += double(starIrradiance(1.0f, star.magnitude));
            for (int k = 0; k < 9; ++k) brighterThan[k] += star.magnitude < float(k - 1) ? 1.0 : 0.0;
            ASSERT_GE(star.magnitude, kStarBrightest - 1e-4f);
            ASSERT_LE(star.magnitude, kStarFaintest + 1e-4f);
            ASSERT_NEAR(luminance(star.colour), 1.0f, 1e-5f);
        }
    const double a0 = std::pow(10.0, 0.5 * kStarBrightest), a1 = std::pow(10.0, 0.5 * kStarFaintest);
    const double expectedCount = double(starsBrighterThan(kStarFaintest) - starsBrighterThan(kStarBrightest));
    const double meanIrradiance = 5.0 * (std::pow(10.0, 0.1 * kStarFaintest) - std::pow(10.0, 0.1 * kStarBrightest)) / (a1 - a0);
    EXPECT_NEAR(count / expectedCount, 1.0, 3.0 / std::sqrt(expectedCount));
    EXPECT_NEAR(total / (expectedCount * meanIrradiance), 1.0, 0.15);
    // The counts brighter than magnitudes 2 to 6 (hundreds to thousands of stars), each within 3
    // Poisson sigma of N(< m) - N(< -1.5).
    for (int k = 3; k <= 7; ++k) {
        const double expected = double(starsBrighterThan(float(k - 1)) - starsBrighterThan(kStarBrightest));
        EXPECT_NEAR(brighterThan[k], expected, 3.0 * std::sqrt(expected)) << "brighter than magnitude " << k - 1;
    }
}

// A star's radiance over its disk integrates to its irradiance: the mean over a fine grid of its
// cell, times the cell's solid angle (4 pi / cells), within 1 %.
TEST(Stars, RadianceIntegratesToTheStarsIrradiance) {
    StarField field;
    field.magnitudeZeroIrradiance = 1.0f;
    int checked = 0;
    for (uint32_t cx = 0; cx < kStarMapSide && checked < 5; ++cx) {
        const Star star = starInCell(cx, 500);
        if (!star.present) continue;
        constexpr int kGrid = 400;
        double sum = 0;
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i) {
                const Vec2f uv{(float(cx) + (float(i) + 0.5f) / kGrid) / float(kStarMapSide),
                               (500.0f + (float(j) + 0.5f) / kGrid) / float(kStarMapSide)};
                sum += double(luminance(starRadianceAt(field, uv)));
            }
        const double cellSolidAngle = 4.0 * kPi / (double(kStarMapSide) * kStarMapSide);
        EXPECT_NEAR(sum / (kGrid * kGrid) * cellSolidAngle / double(starIrradiance(1.0f, star.magnitude)), 1.0, 0.01);
        ++checked;
    }
    EXPECT_EQ(checked, 5);
}

// The celestial sphere's turn: the north celestial pole stands at the latitude's elevation due
// north; a star on the equator at hour angle 0 (right ascension = local sidereal time) stands due
// south at 90 - latitude; six sidereal hours later it sets due west.
TEST(Stars, TurnWithSiderealTimeAndLatitude) {
    const double latitude = 50.0, lst = 75.0;
    const StarField field = makeStarField(lst, latitude, 1.0f);
    const auto worldOf = [&](double ra, double dec) {  // the world direction of a celestial one
        const double a = ra * kPi / 180.0, d = dec * kPi / 180.0;
        const Vec3f c{float(std::cos(d) * std::cos(a)), float(std::cos(d) * std::sin(a)), float(std::sin(d))};
        // celestialFromWorld is a rotation: world = its transpose times c.
        return field.celestialFromWorld[0] * c.x + field.celestialFromWorld[1] * c.y + field.celestialFromWorld[2] * c.z;
    };
    const float s = float(std::sin(latitude * kPi / 180.0)), co = float(std::cos(latitude * kPi / 180.0));
    const Vec3f pole = worldOf(0.0, 90.0), meridian = worldOf(lst, 0.0), setting = worldOf(lst - 90.0, 0.0);
    EXPECT_NEAR(pole.y, s, 1e-6f);
    EXPECT_NEAR(pole.z, -co, 1e-6f);   // north is -z
    EXPECT_NEAR(meridian.y, co, 1e-6f);
    EXPECT_NEAR(meridian.z, s, 1e-6f); // south is +z
    EXPECT_NEAR(setting.x, -1.0f, 1e-6f);  // west is -x
}

} // namespace
} // namespace urbis
