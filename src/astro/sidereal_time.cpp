#include "astro/sidereal_time.h"

#include "astro/horizontal.h"

namespace urbis {

double greenwichSiderealTime(double julianDay) {
    const double d = julianDay - 2451545.0, t = d / 36525.0;
    return wrapDegrees(280.46061837 + 360.98564736629 * d + t * t * (0.000387933 - t / 38710000.0));
}

double localSiderealTime(double julianDay, double longitude) {
    return wrapDegrees(greenwichSiderealTime(julianDay) + longitude);
}

double deltaTSeconds(double year) {
    const double t = year - 2000.0;
    return 62.92 + t * (0.32217 + t * 0.005589);
}

} // namespace urbis
