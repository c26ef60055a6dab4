#include "astro/ephemeris.h"

#include "astro/sidereal_time.h"
#include "astro/solar_position.h"

namespace urbis {

Ephemeris ephemerisAt(const CivilTime& time, double longitude, double latitude) {
    const double jd = julianDayUtc(time);
    return Ephemeris{solarPosition(jd, longitude, latitude), lunarPosition(jd, longitude, latitude),
                     localSiderealTime(jd, longitude)};
}

} // namespace urbis
