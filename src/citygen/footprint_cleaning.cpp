#include "citygen/footprint_cleaning.h"

#include "model/polygon_ops.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr double kMinHoleArea = 0.01;  // m^2

/// Drops points within kFootprintTolerance of their predecessor or of the segment between their
/// neighbours, until none is left (every pass but the last drops a point: at most n + 1 passes).
void dropNeedlessPoints(Ring& ring) {
    for (bool dropped = true; dropped && ring.size() >= 3;) {
        dropped = false;
        for (size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
            const size_t n = ring.size();
            const Vec2d prev = ring[(i + n - 1) % n], p = ring[i], next = ring[(i + 1) % n];
            if (std::hypot(p.x - prev.x, p.y - prev.y) < kFootprintTolerance ||
                distanceToSegment(p, prev, next) < kFootprintTolerance) {
                ring.erase(ring.begin() + std::ptrdiff_t(i));
                dropped = true;
            }
        }
    }
}

/// The smallest distance between two rings that do not cross (GEOS-valid polygons): the least
/// distance from a point of one to an edge of the other.
double ringDistance(const Ring& a, const Ring& b) {
    double d = INFINITY;
    for (int pass = 0; pass < 2; ++pass) {
        const Ring& points = pass == 0 ? a : b;
        const Ring& edges = pass == 0 ? b : a;
        for (const Vec2d p : points)
            for (size_t i = 0; i < edges.size(); ++i) d = std::min(d, distanceToSegment(p, edges[i], edges[(i + 1) % edges.size()]));
    }
    return d;
}

bool finite(const Ring& ring) {
    return std::all_of(ring.begin(), ring.end(), [](Vec2d p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

} // namespace

std::optional<CleanedFootprint> cleanFootprint(const Polygon& footprint) {
    CleanedFootprint out;
    Polygon& polygon = out.polygon;
    polygon.outer = footprint.outer;
    if (!finite(polygon.outer)) return std::nullopt;
    dropNeedlessPoints(polygon.outer);
    if (polygon.outer.size() < 3 || signedArea(polygon.outer) == 0.0) return std::nullopt;
    for (Ring hole : footprint.holes) {
        if (finite(hole)) dropNeedlessPoints(hole);
        const bool apart = finite(hole) && hole.size() >= 3 && std::abs(signedArea(hole)) >= kMinHoleArea &&
                           ringDistance(hole, polygon.outer) >= kFootprintTolerance &&
                           std::all_of(polygon.holes.begin(), polygon.holes.end(),
                                       [&](const Ring& kept) { return ringDistance(hole, kept) >= kFootprintTolerance; });
        if (apart) polygon.holes.push_back(std::move(hole));
        else ++out.holesDropped;
    }
    orient(polygon);
    return out;
}

} // namespace urbis
