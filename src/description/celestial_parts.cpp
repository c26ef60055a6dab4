#include "description/celestial_parts.h"

#include "astro/ephemeris.h"
#include "base/input_error.h"
#include "description/scene_parts.h"

namespace urbis {

namespace {

/// A disk of the sun's record at `sky`, or none (radiance zero) once it is wholly below the horizon,
/// where the ground hides it from every point above it.
Sun diskAt(const Horizontal& sky, double angularRadius, Vec3f irradiance) {
    if (sky.elevation < -angularRadius) return Sun{};
    return makeSun(float(sky.elevation), float(sky.azimuth), float(angularRadius), irradiance);
}

} // namespace

std::array<double, 2> skyLocationOf(const AstronomyDescription& astronomy, const GeoOrigin& origin) {
    if (astronomy.location) return *astronomy.location;
    if (origin.valid) return {origin.lon, origin.lat};
    return kDefaultLocation;
}

std::optional<CivilTime> skyTimeOf(const AstronomyDescription& astronomy) {
    if (astronomy.time.empty()) return std::nullopt;
    std::string error;
    std::optional<CivilTime> time = parseIsoTime(astronomy.time, error);
    if (!time) throw InputError("--time (astronomy.time): '" + astronomy.time + "': " + error, FailureKind::Usage);
    return time;
}

std::optional<double> localHourOf(const AstronomyDescription& astronomy) {
    const std::optional<CivilTime> time = skyTimeOf(astronomy);
    if (!time) return std::nullopt;
    return localClockHour(*time);
}

CelestialLights celestialLightsOf(const SceneDescription& d, const GeoOrigin& origin) {
    CelestialLights out;
    out.sun = sunOf(d.sun);
    const std::optional<CivilTime> time = skyTimeOf(d.astronomy);
    if (!time) return out;
    const auto [lon, lat] = skyLocationOf(d.astronomy, origin);
    const Ephemeris sky = ephemerisAt(*time, lon, lat);
    if (d.astronomy.sunFromTime) out.sun = diskAt(sky.sun, d.sun.angularRadius, d.sun.irradiance);
    const float moonShare = float(lunarIrradianceFraction(sky.moon.phaseAngle, sky.moon.distanceKm));
    out.night.moon = diskAt(sky.moon.sky, sky.moon.angularRadius, d.sun.irradiance * moonShare);
    const float unitsPerLux = float(double(luminance(d.sun.irradiance)) / kSunIlluminanceLux);
    out.night.stars = makeStarField(sky.localSiderealTime, lat, float(kMagnitudeZeroLux) * unitsPerLux);
    return out;
}

} // namespace urbis
