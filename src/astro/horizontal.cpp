#include "astro/horizontal.h"

#include <cmath>
#include <numbers>

namespace urbis {

double radians(double deg) { return deg * std::numbers::pi / 180.0; }
double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }
double wrapDegrees(double angle) {
    const double a = std::fmod(angle, 360.0);
    return a < 0 ? a + 360.0 : a;
}

Horizontal horizontalFromHourAngle(double hourAngle, double declination, double latitude) {
    const double h = radians(hourAngle), d = radians(declination), phi = radians(latitude);
    // East, north and up components of the unit vector towards the body.
    const double east = -std::cos(d) * std::sin(h);
    const double north = std::cos(phi) * std::sin(d) - std::sin(phi) * std::cos(d) * std::cos(h);
    const double up = std::sin(phi) * std::sin(d) + std::cos(phi) * std::cos(d) * std::cos(h);
    return Horizontal{degrees(std::asin(std::fmax(-1.0, std::fmin(1.0, up)))), wrapDegrees(degrees(std::atan2(east, north)))};
}

double refractionCorrection(double elevation) {
    if (elevation > 85.0) return 0.0;
    const double t = std::tan(radians(elevation));
    double arcseconds;
    if (elevation > 5.0) arcseconds = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / std::pow(t, 5.0);
    else if (elevation > -0.575)
        arcseconds = 1735.0 + elevation * (-518.2 + elevation * (103.4 + elevation * (-12.79 + elevation * 0.711)));
    else arcseconds = -20.772 / t;
    return arcseconds / 3600.0;
}

} // namespace urbis
