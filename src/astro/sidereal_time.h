// Sidereal time: the angle the Earth has turned under the stars, which carries the moon and the
// stars across an observer's sky. Host only.
#pragma once

namespace urbis {

/// Greenwich mean sidereal time in degrees, [0, 360), at Julian day `julianDay` (UT): Meeus,
/// "Astronomical Algorithms", formula 12.4.
double greenwichSiderealTime(double julianDay);

/// Local mean sidereal time in degrees, [0, 360), at longitude `longitude` (degrees east).
double localSiderealTime(double julianDay, double longitude);

/// Terrestrial time minus UT in seconds for a decimal year (Espenak and Meeus's polynomial for
/// 2005-2050, used beyond it too: the moon, the only body here it matters for, moves about 0.01
/// degree a minute).
double deltaTSeconds(double year);

} // namespace urbis
