// The tangent-plane projection against geodesic distances on the WGS84 ellipsoid.
#include "osm/geo_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace urbis;

namespace {

constexpr double kA = 6378137.0, kF = 1.0 / 298.257223563, kB = kA * (1.0 - kF);
constexpr double kRad = std::numbers::pi / 180.0;

/// Reference: Vincenty's inverse formula (T. Vincenty, "Direct and inverse solutions of
/// geodesics on the ellipsoid", Survey Review 1975), geodesic distance in metres.
double vincentyDistance(LonLat p, LonLat q) {
    const double l = (q.lon - p.lon) * kRad;
    const double u1 = std::atan((1 - kF) * std::tan(p.lat * kRad));
    const double u2 = std::atan((1 - kF) * std::tan(q.lat * kRad));
    const double sinU1 = std::sin(u1), cosU1 = std::cos(u1), sinU2 = std::sin(u2), cosU2 = std::cos(u2);
    double lambda = l, sigma = 0, sinSigma = 0, cosSigma = 0, cos2Alpha = 0, cos2SigmaM = 0;
    for (int i = 0; i < 200; ++i) {
        const double sinLambda = std::sin(lambda), cosLambda = std::cos(lambda);
        sinSigma = std::hypot(cosU2 * sinLambda, cosU1 * sinU2 - sinU1 * cosU2 * cosLambda);
        cosSigma = sinU1 * sinU2 + cosU1 * cosU2 * cosLambda;
        sigma = std::atan2(sinSigma, cosSigma);
        const double sinAlpha = cosU1 * cosU2 * sinLambda / sinSigma;
        cos2Alpha = 1 - sinAlpha * sinAlpha;
        cos2SigmaM = cos2Alpha != 0 ? cosSigma - 2 * sinU1 * sinU2 / cos2Alpha : 0;
        const double c = kF / 16 * cos2Alpha * (4 + kF * (4 - 3 * cos2Alpha));
        const double previous = lambda;
        lambda = l + (1 - c) * kF * sinAlpha *
                         (sigma + c * sinSigma * (cos2SigmaM + c * cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM)));
        if (std::abs(lambda - previous) < 1e-13) break;
    }
    const double u2b = cos2Alpha * (kA * kA - kB * kB) / (kB * kB);
    const double a = 1 + u2b / 16384 * (4096 + u2b * (-768 + u2b * (320 - 175 * u2b)));
    const double b = u2b / 1024 * (256 + u2b * (-128 + u2b * (74 - 47 * u2b)));
    const double dSigma = b * sinSigma * (cos2SigmaM + b / 4 * (cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM) -
                                          b / 6 * cos2SigmaM * (-3 + 4 * sinSigma * sinSigma) *
                                              (-3 + 4 * cos2SigmaM * cos2SigmaM)));
    return kB * a * (sigma - dSigma);
}

double planeDistance(const GeoProjection& projection, LonLat p, LonLat q) {
    const Vec2d a = projection.project(p), b = projection.project(q);
    return std::hypot(a.x - b.x, a.y - b.y);
}

} // namespace

TEST(GeoProjection, ReferenceMatchesKnownGeodesics) {
    // Published WGS84 values: 1 degree of longitude along the equator (a * pi / 180) and
    // 1 degree of latitude from the equator (meridian arc, 110 574.3 m).
    EXPECT_NEAR(vincentyDistance({0, 0}, {1, 0}), 111319.491, 0.01);
    EXPECT_NEAR(vincentyDistance({0, 0}, {0, 1}), 110574.3, 0.5);
}

TEST(GeoProjection, OriginIsZeroEastIsXNorthIsY) {
    const GeoProjection projection({-122.4, 37.78});
    const Vec2d o = projection.project({-122.4, 37.78});
    EXPECT_NEAR(o.x, 0.0, 1e-9);
    EXPECT_NEAR(o.y, 0.0, 1e-9);
    const Vec2d east = projection.project({-122.39, 37.78});
    const Vec2d north = projection.project({-122.4, 37.79});
    EXPECT_GT(east.x, 800.0);
    EXPECT_NEAR(east.y, 0.0, 1.0); // the parallel bends away from the tangent plane
    EXPECT_GT(north.y, 1000.0);
    EXPECT_NEAR(north.x, 0.0, 1e-6);
}

TEST(GeoProjection, DistancesWithinTenthOfAPercentOverTenKilometres) {
    // Origins from the equator to 60 N; points on a 10 km ring around each, pairs compared
    // with the geodesic distance (origin to point, and point to point across the ring).
    for (const LonLat origin : {LonLat{0.0, 0.0}, LonLat{-122.40, 37.78}, LonLat{13.44, 52.48},
                                LonLat{37.64, 55.76}, LonLat{10.75, 59.91}}) {
        const GeoProjection projection(origin);
        std::vector<LonLat> ring;
        for (int k = 0; k < 12; ++k) {
            const double bearing = k * 30.0 * kRad, radius = 10000.0;
            const double dLat = radius * std::cos(bearing) / 111000.0;
            const double dLon = radius * std::sin(bearing) / (111000.0 * std::cos(origin.lat * kRad));
            ring.push_back({origin.lon + dLon, origin.lat + dLat});
        }
        for (size_t i = 0; i < ring.size(); ++i) {
            const double geodesic = vincentyDistance(origin, ring[i]);
            EXPECT_GT(geodesic, 9000.0);
            EXPECT_NEAR(planeDistance(projection, origin, ring[i]) / geodesic, 1.0, 1e-3)
                << "origin " << origin.lon << "," << origin.lat << " bearing " << i * 30;
            const LonLat q = ring[(i + 5) % ring.size()];
            const double across = vincentyDistance(ring[i], q);
            EXPECT_NEAR(planeDistance(projection, ring[i], q) / across, 1.0, 1e-3);
        }
    }
}

TEST(GeoProjection, UnprojectInvertsProject) {
    const GeoProjection projection(LonLat{-122.41, 37.79});
    for (LonLat p : {LonLat{-122.41, 37.79}, LonLat{-122.38, 37.80}, LonLat{-122.47, 37.73}, LonLat{-121.9, 38.2}}) {
        const LonLat back = projection.unproject(projection.project(p));
        EXPECT_NEAR(back.lon, p.lon, 1e-9);
        EXPECT_NEAR(back.lat, p.lat, 1e-9);
    }
}
