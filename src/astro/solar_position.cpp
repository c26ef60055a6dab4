#include "astro/solar_position.h"

#include <cmath>

namespace urbis {

namespace {

/// Julian centuries from J2000.0.
double centuriesFromJ2000(double julianDay) { return (julianDay - 2451545.0) / 36525.0; }

/// The longitude of the moon's ascending node, radians: the argument of the nutation terms.
double nutationArgument(double t) { return radians(125.04 - 1934.136 * t); }

} // namespace

double obliquityOfEcliptic(double julianDay) {
    const double t = centuriesFromJ2000(julianDay);
    const double mean = 23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
    return mean + 0.00256 * std::cos(nutationArgument(t));
}

SolarCoordinates solarCoordinates(double julianDay) {
    // The NOAA spreadsheet's columns, in its order; T in Julian centuries from J2000.0.
    const double t = centuriesFromJ2000(julianDay);
    const double meanLongitude = wrapDegrees(280.46646 + t * (36000.76983 + t * 0.0003032));
    const double meanAnomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t);
    const double eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    const double m = radians(meanAnomaly);
    const double centre = std::sin(m) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                          std::sin(2 * m) * (0.019993 - 0.000101 * t) + std::sin(3 * m) * 0.000289;
    const double trueLongitude = meanLongitude + centre;
    const double trueAnomaly = meanAnomaly + centre;
    const double omega = nutationArgument(t);
    SolarCoordinates s;
    s.distanceAu = 1.000001018 * (1 - eccentricity * eccentricity) / (1 + eccentricity * std::cos(radians(trueAnomaly)));
    s.apparentLongitude = trueLongitude - 0.00569 - 0.00478 * std::sin(omega);
    const double obliquity = radians(obliquityOfEcliptic(julianDay));
    const double lambda = radians(s.apparentLongitude);
    s.rightAscension = wrapDegrees(degrees(std::atan2(std::cos(obliquity) * std::sin(lambda), std::cos(lambda))));
    s.declination = degrees(std::asin(std::sin(obliquity) * std::sin(lambda)));
    const double y = std::tan(obliquity / 2) * std::tan(obliquity / 2), l0 = radians(meanLongitude);
    s.equationOfTime = 4.0 * degrees(y * std::sin(2 * l0) - 2 * eccentricity * std::sin(m) +
                                     4 * eccentricity * y * std::sin(m) * std::cos(2 * l0) -
                                     0.5 * y * y * std::sin(4 * l0) - 1.25 * eccentricity * eccentricity * std::sin(2 * m));
    return s;
}

Horizontal solarPosition(double julianDay, double longitude, double latitude) {
    const SolarCoordinates s = solarCoordinates(julianDay);
    // True solar time in minutes from the UTC clock (the spreadsheet's "time past local midnight"
    // with its time zone taken out), and the hour angle from it.
    const double utcMinutes = (julianDay + 0.5 - std::floor(julianDay + 0.5)) * 1440.0;
    const double trueSolarMinutes = std::fmod(std::fmod(utcMinutes + s.equationOfTime + 4.0 * longitude, 1440.0) + 1440.0, 1440.0);
    const double hourAngle = trueSolarMinutes / 4.0 - 180.0;
    Horizontal h = horizontalFromHourAngle(hourAngle, s.declination, latitude);
    h.elevation = apparentElevation(h.elevation);
    return h;
}

} // namespace urbis
