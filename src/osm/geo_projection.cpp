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
    : origin_(origin), sinLat_(std::sin(origin.lat * kRadians)), cosLat_(std::cos(origin.lat * kRadians)),
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

LonLat GeoProjection::unproject(Vec2d local) const {
    constexpr double kStep = 1e-5; // degrees, for the Jacobian by differences
    LonLat p = origin_;
    for (int iteration = 0; iteration < 6; ++iteration) {
        const Vec2d at = project(p);
        const Vec2d dLon = project({p.lon + kStep, p.lat}), dLat = project({p.lon, p.lat + kStep});
        const double a = (dLon.x - at.x) / kStep, b = (dLat.x - at.x) / kStep;
        const double c = (dLon.y - at.y) / kStep, d = (dLat.y - at.y) / kStep;
        const double ex = local.x - at.x, ey = local.y - at.y, det = a * d - b * c;
        p = {p.lon + (d * ex - b * ey) / det, p.lat + (a * ey - c * ex) / det};
    }
    return p;
}

} // namespace urbis
