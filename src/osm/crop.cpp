#include "osm/crop.h"

namespace urbis {

namespace {

/// Narrows [t0, t1] to the part of a + t*(b - a) inside the box; false when none is.
bool clipSegment(LonLat a, LonLat b, const GeoBox& box, double& t0, double& t1) {
    const double dx = b.lon - a.lon, dy = b.lat - a.lat;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.lon - box.minLon, box.maxLon - a.lon, a.lat - box.minLat, box.maxLat - a.lat};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) t0 = t > t0 ? t : t0;
        else t1 = t < t1 ? t : t1;
    }
    return t0 <= t1;
}

/// The point at t along a -> b; exactly b at t = 1 (a + (b - a) may round elsewhere), so that a
/// vertex inside the box keeps its bits and stays equal to the node at the same place.
LonLat lerp(LonLat a, LonLat b, double t) {
    if (t == 1.0) return b;
    return {a.lon + t * (b.lon - a.lon), a.lat + t * (b.lat - a.lat)};
}

} // namespace

std::vector<std::vector<LonLat>> clipPolyline(const std::vector<LonLat>& line, const GeoBox& box) {
    std::vector<std::vector<LonLat>> pieces;
    std::vector<LonLat> piece;
    const auto flush = [&] {
        if (piece.size() >= 2) pieces.push_back(std::move(piece));
        piece.clear();
    };
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        double t0 = 0.0, t1 = 1.0;
        if (!clipSegment(line[i], line[i + 1], box, t0, t1)) {
            flush();
            continue;
        }
        if (t0 > 0.0) flush(); // entering through the border
        if (piece.empty()) piece.push_back(lerp(line[i], line[i + 1], t0));
        piece.push_back(lerp(line[i], line[i + 1], t1));
        if (t1 < 1.0) flush(); // leaving through the border
    }
    flush();
    return pieces;
}

} // namespace urbis
