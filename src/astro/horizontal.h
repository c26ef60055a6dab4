// From the equator's coordinates to the observer's horizon, shared by the sun and the moon, and the
// atmosphere's refraction of what is seen there. Degrees throughout. Host only.
#pragma once

namespace urbis {

/// Where a body stands in an observer's sky.
struct Horizontal {
    double elevation = 0;  ///< degrees above the horizon
    double azimuth = 0;    ///< degrees clockwise from north, [0, 360)
};

/// The geometric elevation and azimuth of a body at `hourAngle` (degrees west of the meridian) and
/// declination `declination` seen from latitude `latitude` (Meeus, "Astronomical Algorithms",
/// formulae 13.5 and 13.6, with the azimuth turned to start at north).
Horizontal horizontalFromHourAngle(double hourAngle, double declination, double latitude);

/// The rise in elevation (degrees) that refraction gives a body at geometric elevation `elevation`:
/// the NOAA Solar Calculator's piecewise formula (Bennett-like above 5 degrees, a polynomial near
/// the horizon, zero above 85 degrees).
double refractionCorrection(double elevation);

/// The apparent (refracted) elevation of a body at geometric elevation `elevation`.
inline double apparentElevation(double elevation) { return elevation + refractionCorrection(elevation); }

/// Degrees to radians and back, and an angle taken into [0, 360).
double radians(double degrees);
double degrees(double radians);
double wrapDegrees(double angle);

} // namespace urbis
