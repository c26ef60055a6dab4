// The sun's position by date, time and place: NOAA's solar position algorithm (the NOAA Solar
// Calculator and its spreadsheet, NOAA Global Monitoring Laboratory; after Meeus, "Astronomical
// Algorithms", chapters 25 and 28). About 0.01 degree from 1901 to 2099, well inside what a render
// needs. Host only.
#pragma once

#include "astro/horizontal.h"

namespace urbis {

/// The sun seen from the Earth's centre at one instant.
struct SolarCoordinates {
    double apparentLongitude = 0;  ///< ecliptic, degrees (with nutation and aberration, as NOAA)
    double rightAscension = 0;     ///< degrees, [0, 360)
    double declination = 0;        ///< degrees
    double distanceAu = 1;         ///< Earth-sun distance, astronomical units
    double equationOfTime = 0;     ///< minutes: apparent minus mean solar time
};

/// The obliquity of the ecliptic (degrees) at Julian day `julianDay`: Meeus 22.2 with the nutation
/// term of the NOAA spreadsheet.
double obliquityOfEcliptic(double julianDay);

/// The sun's geocentric coordinates at Julian day `julianDay` (UTC, as NOAA takes it).
SolarCoordinates solarCoordinates(double julianDay);

/// The sun's apparent (refracted) elevation and azimuth seen from `longitude`, `latitude`
/// (degrees, east and north positive) at Julian day `julianDay` (UTC).
Horizontal solarPosition(double julianDay, double longitude, double latitude);

} // namespace urbis
