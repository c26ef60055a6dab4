#include "astro/lunar_position.h"

#include "astro/sidereal_time.h"
#include "astro/solar_position.h"

#include <cmath>
#include <numbers>

namespace urbis {

namespace {

/// One periodic term: multiples of D, M, M', F and its coefficient (1e-6 degree, or 1e-3 km).
struct LunarTerm {
    signed char d, m, mp, f;
    double coefficient;
};

// Meeus table 47.A, longitude (sin) and distance (cos): every term of at least 0.001 degree and
// the distance's terms of at least 1 km.
constexpr LunarTerm kLongitude[] = {
    {0, 0, 1, 0, 6288774}, {2, 0, -1, 0, 1274027}, {2, 0, 0, 0, 658314}, {0, 0, 2, 0, 213618},
    {0, 1, 0, 0, -185116}, {0, 0, 0, 2, -114332},  {2, 0, -2, 0, 58793}, {2, -1, -1, 0, 57066},
    {2, 0, 1, 0, 53322},   {2, -1, 0, 0, 45758},   {0, 1, -1, 0, -40923}, {1, 0, 0, 0, -34720},
    {0, 1, 1, 0, -30383},  {2, 0, 0, -2, 15327},   {0, 0, 1, 2, -12528}, {0, 0, 1, -2, 10980},
    {4, 0, -1, 0, 10675},  {0, 0, 3, 0, 10034},    {4, 0, -2, 0, 8548},  {2, 1, -1, 0, -7888},
    {2, 1, 0, 0, -6766},   {1, 0, -1, 0, -5163},   {1, 1, 0, 0, 4987},   {2, -1, 1, 0, 4036},
    {2, 0, 2, 0, 3994},    {4, 0, 0, 0, 3861},     {2, 0, -3, 0, 3665},  {0, 1, -2, 0, -2689},
    {2, 0, -1, 2, -2602},  {2, -1, -2, 0, 2390},   {1, 0, 1, 0, -2348},  {2, -2, 0, 0, 2236},
    {0, 1, 2, 0, -2120},   {0, 2, 0, 0, -2069},    {2, -2, -1, 0, 2048}, {2, 0, 1, -2, -1773},
    {2, 0, 0, 2, -1595},   {4, -1, -1, 0, 1215},   {0, 0, 2, 2, -1110},
};
constexpr LunarTerm kDistance[] = {
    {0, 0, 1, 0, -20905355}, {2, 0, -1, 0, -3699111}, {2, 0, 0, 0, -2955968}, {0, 0, 2, 0, -569925},
    {0, 1, 0, 0, 48888},     {0, 0, 0, 2, -3149},     {2, 0, -2, 0, 246158},  {2, -1, -1, 0, -152138},
    {2, 0, 1, 0, -170733},   {2, -1, 0, 0, -204586},  {0, 1, -1, 0, -129620}, {1, 0, 0, 0, 108743},
    {0, 1, 1, 0, 104755},    {2, 0, 0, -2, 10321},    {0, 0, 1, -2, 79661},   {4, 0, -1, 0, -34782},
    {0, 0, 3, 0, -23210},    {4, 0, -2, 0, -21636},   {2, 1, -1, 0, 24208},   {2, 1, 0, 0, 30824},
    {1, 0, -1, 0, -8379},    {1, 1, 0, 0, -16675},    {2, -1, 1, 0, -12831},  {2, 0, 2, 0, -10445},
    {4, 0, 0, 0, -11650},    {2, 0, -3, 0, 14403},    {0, 1, -2, 0, -7003},   {2, -1, -2, 0, 10056},
    {1, 0, 1, 0, 6322},      {2, -2, 0, 0, -9884},    {0, 1, 2, 0, 5751},     {2, -2, -1, 0, -4950},
    {2, 0, 1, -2, 4130},     {4, -1, -1, 0, -3958},   {3, 0, -1, 0, 3258},    {2, 1, 1, 0, 2616},
    {4, -1, -2, 0, -1897},   {0, 2, -1, 0, -2117},    {2, 2, -1, 0, 2354},
};
// Meeus table 47.B, latitude (sin): every term of at least 0.001 degree.
constexpr LunarTerm kLatitude[] = {
    {0, 0, 0, 1, 5128122}, {0, 0, 1, 1, 280602}, {0, 0, 1, -1, 277693}, {2, 0, 0, -1, 173237},
    {2, 0, -1, 1, 55413},  {2, 0, -1, -1, 46271}, {2, 0, 0, 1, 32573},  {0, 0, 2, 1, 17198},
    {2, 0, 1, -1, 9266},   {0, 0, 2, -1, 8822},   {2, -1, 0, -1, 8216}, {2, 0, -2, -1, 4324},
    {2, 0, 1, 1, 4200},    {2, 1, 0, -1, -3359},  {2, -1, -1, 1, 2463}, {2, -1, 0, 1, 2211},
    {2, -1, -1, -1, 2065}, {0, 1, -1, -1, -1870}, {4, 0, -1, -1, 1828}, {0, 1, 0, 1, -1794},
    {0, 0, 0, 3, -1749},   {0, 1, -1, 1, -1565},  {1, 0, 0, 1, -1491},  {0, 1, 1, 1, -1475},
    {0, 1, 1, -1, -1410},  {0, 1, 0, -1, -1344},  {1, 0, 0, -1, -1335}, {0, 0, 3, 1, 1107},
    {4, 0, 0, -1, 1021},   {4, 0, -1, 1, 833},
};

/// Sum of `terms` with sin (or cos) of their arguments; terms in M carry the eccentricity factor E
/// once per multiple of M (Meeus 47.6).
template <size_t N>
double sumTerms(const LunarTerm (&terms)[N], double d, double m, double mp, double f, double e, bool useCos) {
    double sum = 0;
    for (const LunarTerm& term : terms) {
        const double argument = term.d * d + term.m * m + term.mp * mp + term.f * f;
        const double factor = term.m == 0 ? 1.0 : (std::abs(term.m) == 1 ? e : e * e);
        sum += term.coefficient * factor * (useCos ? std::cos(argument) : std::sin(argument));
    }
    return sum;
}

/// A polynomial in T with coefficients from the constant term up.
double poly(double t, double c0, double c1, double c2, double c3, double c4) {
    return c0 + t * (c1 + t * (c2 + t * (c3 + t * c4)));
}

constexpr double kAuKm = 149597870.7;
constexpr double kEarthRadiusKm = 6378.14;

} // namespace

LunarCoordinates lunarCoordinates(double julianEphemerisDay) {
    const double t = (julianEphemerisDay - 2451545.0) / 36525.0;
    // Meeus 47.1-47.5: the moon's mean longitude, the mean elongation, the sun's and the moon's mean
    // anomalies, the argument of latitude; 47.6 the eccentricity factor.
    const double lp = radians(wrapDegrees(poly(t, 218.3164477, 481267.88123421, -0.0015786, 1.0 / 538841, -1.0 / 65194000)));
    const double d = radians(wrapDegrees(poly(t, 297.8501921, 445267.1114034, -0.0018819, 1.0 / 545868, -1.0 / 113065000)));
    const double m = radians(wrapDegrees(poly(t, 357.5291092, 35999.0502909, -0.0001536, 1.0 / 24490000, 0)));
    const double mp = radians(wrapDegrees(poly(t, 134.9633964, 477198.8675055, 0.0087414, 1.0 / 69699, -1.0 / 14712000)));
    const double f = radians(wrapDegrees(poly(t, 93.2720950, 483202.0175233, -0.0036539, -1.0 / 3526000, 1.0 / 863310000)));
    const double e = 1.0 - t * (0.002516 + t * 0.0000074);
    const double a1 = radians(119.75 + 131.849 * t), a2 = radians(53.09 + 479264.290 * t), a3 = radians(313.45 + 481266.484 * t);
    // The additive terms of Venus (A1), Jupiter (A2) and the Earth's flattening (L').
    const double sl = sumTerms(kLongitude, d, m, mp, f, e, false) + 3958 * std::sin(a1) + 1962 * std::sin(lp - f) +
                      318 * std::sin(a2);
    const double sb = sumTerms(kLatitude, d, m, mp, f, e, false) - 2235 * std::sin(lp) + 382 * std::sin(a3) +
                      175 * std::sin(a1 - f) + 175 * std::sin(a1 + f) + 127 * std::sin(lp - mp) - 115 * std::sin(lp + mp);
    const double sr = sumTerms(kDistance, d, m, mp, f, e, true);
    return LunarCoordinates{wrapDegrees(degrees(lp) + sl * 1e-6), sb * 1e-6, 385000.56 + sr * 1e-3};
}

double lunarPhaseAngle(const LunarCoordinates& moon, double sunLongitude, double sunDistanceKm) {
    const double cosElongation = std::cos(radians(moon.latitude)) * std::cos(radians(moon.longitude - sunLongitude));
    const double elongation = std::acos(std::fmax(-1.0, std::fmin(1.0, cosElongation)));
    return degrees(std::atan2(sunDistanceKm * std::sin(elongation), moon.distanceKm - sunDistanceKm * std::cos(elongation)));
}

double lunarIrradianceFraction(double phaseAngle, double distanceKm) {
    const double a = radians(phaseAngle);
    const double lambertPhase = (std::sin(a) + (std::numbers::pi - a) * std::cos(a)) / std::numbers::pi;
    const double ratio = kMoonRadiusKm / distanceKm;
    return kMoonGeometricAlbedo * ratio * ratio * std::fmax(0.0, lambertPhase);
}

LunarPosition lunarPosition(double julianDay, double longitude, double latitude) {
    const double year = 2000.0 + (julianDay - 2451545.0) / 365.25;
    const LunarCoordinates moon = lunarCoordinates(julianDay + deltaTSeconds(year) / 86400.0);
    const double epsilon = radians(obliquityOfEcliptic(julianDay));
    const double lambda = radians(moon.longitude), beta = radians(moon.latitude);
    // Meeus 13.3 and 13.4: ecliptic to equatorial.
    const double rightAscension = degrees(std::atan2(std::sin(lambda) * std::cos(epsilon) - std::tan(beta) * std::sin(epsilon), std::cos(lambda)));
    const double declination = degrees(std::asin(std::sin(beta) * std::cos(epsilon) + std::cos(beta) * std::sin(epsilon) * std::sin(lambda)));
    LunarPosition p;
    p.sky = horizontalFromHourAngle(localSiderealTime(julianDay, longitude) - rightAscension, declination, latitude);
    // Parallax: seen from the surface rather than the centre, the moon sits lower by up to its
    // horizontal parallax (about 0.95 degree).
    p.sky.elevation -= degrees(std::asin(kEarthRadiusKm / moon.distanceKm * std::cos(radians(p.sky.elevation))));
    p.sky.elevation = apparentElevation(p.sky.elevation);
    p.distanceKm = moon.distanceKm;
    const SolarCoordinates sun = solarCoordinates(julianDay);
    p.phaseAngle = lunarPhaseAngle(moon, sun.apparentLongitude, sun.distanceAu * kAuKm);
    p.illuminatedFraction = 0.5 * (1.0 + std::cos(radians(p.phaseAngle)));
    p.angularRadius = degrees(std::asin(kMoonRadiusKm / moon.distanceKm));
    return p;
}

} // namespace urbis
