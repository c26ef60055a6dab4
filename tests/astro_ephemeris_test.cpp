// The sun's and the moon's positions (astro/) against published values, each cited where it is used.
#include "astro/civil_time.h"
#include "astro/lunar_position.h"
#include "astro/sidereal_time.h"
#include "astro/solar_position.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

double julianDayOf(const char* iso) {
    std::string error;
    const std::optional<CivilTime> t = parseIsoTime(iso, error);
    EXPECT_TRUE(t.has_value()) << iso << ": " << error;
    return t ? julianDayUtc(*t) : 0.0;
}

/// The difference of two angles in degrees, in [-180, 180).
double angleDifference(double a, double b) { return wrapDegrees(a - b + 180.0) - 180.0; }

TEST(AstroSun, MatchesNrelSpaExample) {
    // Reda and Andreas, "Solar Position Algorithm for Solar Radiation Applications", NREL/TP-560-34302
    // (2008), table A5.1: 2003-10-17 12:30:30 at -7 h, latitude 39.742476, longitude -105.1786 gives a
    // topocentric zenith of 50.11162 degrees (refracted) and an azimuth of 194.34024 degrees.
    const Horizontal sun = solarPosition(julianDayOf("2003-10-17T12:30:30-07:00"), -105.1786, 39.742476);
    EXPECT_NEAR(90.0 - sun.elevation, 50.11162, 0.1);
    EXPECT_NEAR(sun.azimuth, 194.34024, 0.1);
}

TEST(AstroSun, MatchesMeeusExample25a) {
    // Meeus, "Astronomical Algorithms" (2nd ed.), example 25.a, 1992 October 13.0 TD (the same
    // low-accuracy series as NOAA's): apparent right ascension 198.38083, declination -7.78507 degrees,
    // distance 0.99766 AU.
    const SolarCoordinates sun = solarCoordinates(2448908.5);
    EXPECT_NEAR(sun.rightAscension, 198.38083, 0.001);
    EXPECT_NEAR(sun.declination, -7.78507, 0.001);
    EXPECT_NEAR(sun.distanceAu, 0.99766, 0.00001);
}

TEST(AstroSun, ReachesTheSeasonsWhenPublished) {
    // US Naval Observatory, "Earth's Seasons and Apsides" for 2024 (to the minute, UT): the sun's
    // apparent longitude is 0, 90, 180 and 270 degrees at the equinoxes and solstices. It moves 0.04
    // degree an hour, so half a minute is 0.0003 degree.
    const std::pair<const char*, double> seasons[] = {{"2024-03-20T03:06Z", 0.0},
                                                      {"2024-06-20T20:51Z", 90.0},
                                                      {"2024-09-22T12:44Z", 180.0},
                                                      {"2024-12-21T09:20Z", 270.0}};
    for (const auto& [iso, longitude] : seasons)
        EXPECT_NEAR(angleDifference(solarCoordinates(julianDayOf(iso)).apparentLongitude, longitude), 0.0, 0.01) << iso;
    // At the June solstice the declination is the obliquity (23.44 degrees in 2024, the Astronomical
    // Almanac's 23 26' 18").
    EXPECT_NEAR(solarCoordinates(julianDayOf("2024-06-20T20:51Z")).declination, 23.4383, 0.005);
}

TEST(AstroSun, StandsAtTheZenithWhereTheDeclinationAndHourAngleSay) {
    // Where the sun is overhead (the subsolar point: latitude its declination, longitude where the
    // hour angle is zero) its elevation is 90 degrees; a quarter turn of the Earth later it sets.
    const double jd = julianDayOf("2024-06-20T20:51Z");
    const SolarCoordinates s = solarCoordinates(jd);
    const double utcMinutes = 20 * 60 + 51;
    const double subsolarLongitude = -(utcMinutes + s.equationOfTime - 720.0) / 4.0;
    EXPECT_GT(solarPosition(jd, subsolarLongitude, s.declination).elevation, 89.9);
    EXPECT_NEAR(solarPosition(jd, subsolarLongitude - 90.0, 0.0).elevation, 0.0, 0.8);  // refraction lifts it
}

TEST(AstroSiderealTime, MatchesMeeusExamples12aAnd12b) {
    // Meeus example 12.a: 1987 April 10, 0h UT: 13h10m46.3668s = 197.693195 degrees. Example 12.b:
    // 1987 April 10, 19h21m00s UT: 8h34m57.0896s = 128.7378734 degrees.
    EXPECT_NEAR(greenwichSiderealTime(julianDayOf("1987-04-10T00:00Z")), 197.693195, 1e-5);
    EXPECT_NEAR(greenwichSiderealTime(julianDayOf("1987-04-10T19:21Z")), 128.7378734, 1e-5);
    EXPECT_NEAR(localSiderealTime(julianDayOf("1987-04-10T19:21Z"), -77.0), 51.7378734, 1e-5);
}

TEST(AstroMoon, MatchesMeeusExample47a) {
    // Meeus example 47.a, 1992 April 12, 0h TD (JDE 2448724.5): lambda = 133.162655, beta = -3.229126
    // degrees, distance 368409.7 km (the full series of tables 47.A and 47.B).
    // Only their largest terms are kept here (astro/lunar_position.cpp): within 0.01 degree and 15 km
    // (measured: 0.0013 degree, 0.0006 degree, 11.5 km).
    const LunarCoordinates moon = lunarCoordinates(2448724.5);
    EXPECT_NEAR(moon.longitude, 133.162655, 0.01);
    EXPECT_NEAR(moon.latitude, -3.229126, 0.01);
    EXPECT_LT(std::fabs(moon.distanceKm - 368409.7), 15.0);
}

TEST(AstroMoon, MatchesMeeusExample48aPhase) {
    // Meeus example 48.a, the same instant: phase angle 69.0756 degrees, illuminated fraction 0.6786
    // (computed there with the sun's position of chapter 25, as here).
    const LunarCoordinates moon = lunarCoordinates(2448724.5);
    const SolarCoordinates sun = solarCoordinates(2448724.5);
    const double phase = lunarPhaseAngle(moon, sun.apparentLongitude, sun.distanceAu * 149597870.7);
    EXPECT_NEAR(phase, 69.0756, 0.02);
    EXPECT_NEAR(0.5 * (1.0 + std::cos(radians(phase))), 0.6786, 0.0005);
}

TEST(AstroMoon, IsFullAndNewWhenPublished) {
    // US Naval Observatory, "Phases of the Moon" for 2024: full moon 2024-04-23 23:49 UT, new moon
    // 2024-04-08 18:21 UT (the total solar eclipse). The illuminated fraction is near 1 and 0.
    EXPECT_GT(lunarPosition(julianDayOf("2024-04-23T23:49Z"), 0.0, 0.0).illuminatedFraction, 0.99);
    EXPECT_LT(lunarPosition(julianDayOf("2024-04-08T18:21Z"), 0.0, 0.0).illuminatedFraction, 0.01);
}

TEST(AstroMoon, CoversTheSunAtTheEclipse) {
    // NASA's eclipse page (Espenak), 2024 April 8: greatest eclipse at 18:17:16 UT (TD 18:18:29) at
    // 25 17.4' N, 104 08.3' W, the sun at 69.8 degrees elevation. There the moon's centre is on the sun's,
    // within a few hundredths of a degree; the disks' radii are about 0.27 degree.
    const double jd = julianDayOf("2024-04-08T18:17:16Z");
    const Horizontal sun = solarPosition(jd, -104.138, 25.29);
    const LunarPosition moon = lunarPosition(jd, -104.138, 25.29);
    EXPECT_NEAR(sun.elevation, 69.8, 0.1);
    EXPECT_NEAR(moon.sky.elevation, sun.elevation, 0.05);
    EXPECT_NEAR(angleDifference(moon.sky.azimuth, sun.azimuth) * std::cos(radians(sun.elevation)), 0.0, 0.05);
}

TEST(AstroMoon, FullMoonIsAbout400000TimesFainterThanTheSun) {
    // The full moon's magnitude -12.74 against the sun's -26.74 (Allen's Astrophysical Quantities):
    // 10^(14 / 2.5) = 398,000. The Lambertian sphere of geometric albedo 0.12 at the mean distance
    // gives 1 / 408,000, within 10 %.
    const double fraction = lunarIrradianceFraction(0.0, 384400.0);
    EXPECT_NEAR(1.0 / fraction, 398000.0, 40000.0);
    // Lambert's phase law: half the disk lit (a quarter) gives 1/pi of full.
    EXPECT_NEAR(lunarIrradianceFraction(90.0, 384400.0) / fraction, 1.0 / 3.14159265, 1e-6);
    EXPECT_LT(lunarIrradianceFraction(180.0, 384400.0), 1e-20);  // new moon: dark (to rounding)
}

} // namespace
} // namespace urbis
