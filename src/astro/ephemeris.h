// Everything the sky needs of one moment at one place: the sun, the moon and the turn of the stars.
// What `urbis sun` prints and what a render's sun, moon and stars are made from. Host only.
#pragma once

#include "astro/civil_time.h"
#include "astro/lunar_position.h"

namespace urbis {

struct Ephemeris {
    Horizontal sun;                  ///< apparent (refracted), NOAA's algorithm (astro/solar_position.h)
    LunarPosition moon;              ///< apparent, with parallax and phase (astro/lunar_position.h)
    double localSiderealTime = 0;    ///< degrees: the right ascension on the meridian
};

/// The sky at `time` seen from `longitude`, `latitude` (degrees, east and north positive).
Ephemeris ephemerisAt(const CivilTime& time, double longitude, double latitude);

} // namespace urbis
