// Longitude/latitude to local metres on the plane tangent to the WGS84 ellipsoid.
#pragma once

#include "model/city_model.h"

namespace urbis {

/// A WGS84 position in degrees.
struct LonLat {
    double lon = 0, lat = 0;
};

/// Projects WGS84 positions (height 0) to east-north-up metres around an origin:
/// geodetic -> ECEF -> ENU, keeping east (x) and north (y). Over a city (10 km) the
/// distances it gives differ from geodesic ones by far less than 0.1%.
class GeoProjection {
public:
    /// Tangent plane at `origin` (degrees).
    explicit GeoProjection(LonLat origin);

    /// Local metres (x east, y north) of a position in degrees.
    Vec2d project(LonLat p) const;

    /// The position in degrees (height 0) that project() takes to `local` metres; by Newton
    /// steps on project(), to well under a millimetre over a city.
    LonLat unproject(Vec2d local) const;

private:
    LonLat origin_;
    double ecef0_[3];
    double sinLat_, cosLat_, sinLon_, cosLon_;
};

} // namespace urbis
