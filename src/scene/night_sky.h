// The lights of the sky besides the sun and the sky's own glow (host+device POD): the moon, a disk
// like the sun and sampled by the same functions (lights/sun_light.h), and the stars, fixed to the
// celestial sphere (lights/star_field.h). Both are dark unless a time is given (docs/astronomy.md).
#pragma once

#include "scene/sun.h"

namespace urbis {

/// The stars: the turn of the celestial sphere over the observer and their brightness scale.
struct StarField {
    /// Rows of the rotation from world directions (x east, y up, z south) to the celestial sphere's
    /// equatorial frame (x towards right ascension 0 on the equator, z the north celestial pole).
    Vec3f celestialFromWorld[3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    /// Irradiance of a star of magnitude 0 on a surface facing it, in the renderer's units; 0: no stars.
    float magnitudeZeroIrradiance = 0.0f;
};

struct NightSky {
    Sun moon;          ///< radiance zero: no moon (no time given, or below the horizon)
    StarField stars;
};

/// The star field seen at local sidereal time `localSiderealTime` (degrees) from latitude
/// `latitude` (degrees), with `magnitudeZeroIrradiance` as StarField says.
StarField makeStarField(double localSiderealTime, double latitude, float magnitudeZeroIrradiance);

} // namespace urbis
