#include "scene/night_sky.h"

#include <cmath>
#include <numbers>

namespace urbis {

StarField makeStarField(double localSiderealTime, double latitude, float magnitudeZeroIrradiance) {
    // A star at right ascension a and declination d has hour angle H = LST - a; its east, north and
    // up components (Meeus 13.5-13.6 as vectors) are linear in the equatorial unit vector
    // (cos d cos a, cos d sin a, sin d). World x is east, y up, z south; the inverse of a rotation
    // is its transpose, so the world-from-celestial matrix's columns are these rows.
    const double l = localSiderealTime * std::numbers::pi / 180.0, phi = latitude * std::numbers::pi / 180.0;
    const double sl = std::sin(l), cl = std::cos(l), sp = std::sin(phi), cp = std::cos(phi);
    const double worldFromCelestial[3][3] = {{-sl, cl, 0.0}, {cp * cl, cp * sl, sp}, {sp * cl, sp * sl, -cp}};
    StarField stars;
    for (int row = 0; row < 3; ++row)
        stars.celestialFromWorld[row] = Vec3f{float(worldFromCelestial[0][row]), float(worldFromCelestial[1][row]),
                                              float(worldFromCelestial[2][row])};
    stars.magnitudeZeroIrradiance = magnitudeZeroIrradiance;
    return stars;
}

} // namespace urbis
