#include "osm/geo_projection.h"

#include <cmath>
#include <numbers>

namespace urbis {

namespace {
constexpr double kWgs84A = 6378137.0;                 // semi-major axis, m
constexpr double kWgs84F = 1.0 / 298.257223563;       // flattening
constexpr double kWgs84E2 = kWgs84F * (2.0 - kWgs84F); // first eccentricity squared
constexpr double kRadians = std::numbers::pi / 180.0;

/// Earth-centred, earth-fixed coordinates in metres of a WGS84 position at height 0.
void ecefFromLonLat(LonLat p, double out[3]) {
    const double lat = p.lat * kRadians, lon = p.lon * kRadians;
    const double sinLat = std::sin(lat), cosLat = std::cos(lat);
    const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * sinLat * sinLat); // prime vertical radius
    out[0] = n * cosLat * std::cos(lon);
    out[1] = n * cosLat * std::sin(lon);
    out[2] = n * (1.0 - kWgs84E2) * sinLat;
}
} // namespace

GeoProjection::GeoProjection(LonLat origin)
    : sinLat_(std::sin(origin.lat * kRadians)), cosLat_(std::cos(origin.lat * kRadians)),
      sinLon_(std::sin(origin.lon * kRadians)), cosLon_(std::cos(origin.lon * kRadians)) {
    ecefFromLonLat(origin, ecef0_);
}

Vec2d GeoProjection::project(LonLat p) const {
    double e[3];
    ecefFromLonLat(p, e);
    const double dx = e[0] - ecef0_[0], dy = e[1] - ecef0_[1], dz = e[2] - ecef0_[2];
    return {-sinLon_ * dx + cosLon_ * dy,
            -sinLat_ * cosLon_ * dx - sinLat_ * sinLon_ * dy + cosLat_ * dz};
}

} // namespace urbis
