// The moon's position and phase by date, time and place: the periodic terms of Meeus, "Astronomical
// Algorithms" (2nd ed., 1998), chapter 47 (after ELP-2000/82), the largest of them: about 0.01
// degree in longitude and latitude, against the several tenths of a degree that the observer's
// parallax adds, which lunarPosition corrects. The phase: chapter 48. Host only.
#pragma once

#include "astro/horizontal.h"

namespace urbis {

/// The moon seen from the Earth's centre.
struct LunarCoordinates {
    double longitude = 0;   ///< geocentric ecliptic longitude, degrees (mean equinox of date, no nutation)
    double latitude = 0;    ///< geocentric ecliptic latitude, degrees
    double distanceKm = 0;  ///< between the centres of the Earth and the moon
};

/// The moon's geocentric ecliptic coordinates at Julian ephemeris day `julianEphemerisDay` (TT).
LunarCoordinates lunarCoordinates(double julianEphemerisDay);

/// The moon seen from a place: where, how far, how much of it is lit.
struct LunarPosition {
    Horizontal sky;                 ///< apparent: topocentric (parallax) and refracted
    double distanceKm = 0;          ///< from the Earth's centre
    double phaseAngle = 0;          ///< sun-moon-Earth angle, degrees: 0 full, 180 new
    double illuminatedFraction = 0; ///< of the disk, (1 + cos phaseAngle) / 2 (Meeus 48.1)
    double angularRadius = 0;       ///< of the disk, degrees
};

/// The moon seen from `longitude`, `latitude` (degrees, east and north positive) at Julian day
/// `julianDay` (UTC; terrestrial time is UT plus deltaTSeconds).
LunarPosition lunarPosition(double julianDay, double longitude, double latitude);

/// The phase angle (degrees) of the moon at `moon` while the sun is at geocentric apparent
/// longitude `sunLongitude` (degrees) and `sunDistanceKm`: Meeus 48.2 and 48.3.
double lunarPhaseAngle(const LunarCoordinates& moon, double sunLongitude, double sunDistanceKm);

/// The moon's irradiance on a surface facing it, as a fraction of the sun's: a sphere of geometric
/// albedo 0.12 whose surface scatters as a Lambertian sphere, (r / d)^2 p Phi(phase angle) with
/// Phi(a) = (sin a + (pi - a) cos a) / pi (Lambert's phase law; Phi(0) = 1). About 1/400,000 at
/// full moon, as the moon's magnitude -12.7 against the sun's -26.7 says.
double lunarIrradianceFraction(double phaseAngle, double distanceKm);

/// The moon's mean radius, km (IAU).
inline constexpr double kMoonRadiusKm = 1737.4;
/// The moon's geometric albedo.
inline constexpr double kMoonGeometricAlbedo = 0.12;

} // namespace urbis
