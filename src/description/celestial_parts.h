// What the scene takes from the description's date, time and place (AstronomyDescription): the
// sun's direction, the moon and the stars; and the local hour for time-of-day effects.
#pragma once

#include "astro/civil_time.h"
#include "description/scene_description.h"
#include "model/city_model.h"
#include "scene/night_sky.h"
#include "scene/sun.h"

#include <array>
#include <optional>

namespace urbis {

/// The direct sun's illuminance (lux) that SunDescription::irradiance stands for: what ties the
/// stars' physical brightness (lux) to the renderer's units.
inline constexpr double kSunIlluminanceLux = 1.0e5;
/// Illuminance of a star of magnitude 0 (lux; Allen's Astrophysical Quantities: 2.54e-6).
inline constexpr double kMagnitudeZeroLux = 2.5e-6;

/// The place the sky is seen from, {LON, LAT} in degrees: astronomy.location where given, else the
/// imported city's origin (the OSM extract's centre) where valid, else kDefaultLocation.
std::array<double, 2> skyLocationOf(const AstronomyDescription& astronomy, const GeoOrigin& origin);

/// astronomy.time parsed; none without one. Throws InputError (usage) if it does not parse, which
/// firstSceneProblem has already ruled out for a checked description.
std::optional<CivilTime> skyTimeOf(const AstronomyDescription& astronomy);

/// The hour of the local clock of astronomy.time, [0, 24) (localClockHour); none without a time.
std::optional<double> localHourOf(const AstronomyDescription& astronomy);

/// The sun, the moon and the stars of a description.
struct CelestialLights {
    Sun sun;
    NightSky night;
};

/// Without a time: the sun of `d.sun`'s angles, no moon, no stars. With one, seen from
/// skyLocationOf(d.astronomy, origin): the sun's direction from NOAA's algorithm (unless
/// `sunFromTime` is false) with d.sun's radius and irradiance, off once its disk is wholly below the
/// horizon; the moon's disk where it stands, of the sun's irradiance times lunarIrradianceFraction,
/// off below the horizon; the stars turned by the local sidereal time and the latitude, at
/// kMagnitudeZeroLux in the sun's units.
CelestialLights celestialLightsOf(const SceneDescription& d, const GeoOrigin& origin);

} // namespace urbis
