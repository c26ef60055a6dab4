#include "model/polygon_ops.h"

#include <algorithm>
#include <cmath>

namespace urbis {

void removeDuplicatePoints(Ring& ring) {
    const auto same = [](Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; };
    ring.erase(std::unique(ring.begin(), ring.end(), same), ring.end());
    while (ring.size() > 1 && same(ring.front(), ring.back())) ring.pop_back();
}

double signedArea(const Ring& ring) {
    double twice = 0;
    for (size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2d a = ring[i], b = ring[(i + 1) % n];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

double area(const Polygon& polygon) {
    double a = std::abs(signedArea(polygon.outer));
    for (const Ring& hole : polygon.holes) a -= std::abs(signedArea(hole));
    return a;
}

Vec2d centroid(const Ring& ring) {
    if (ring.empty()) return {};
    // Relative to the first point, so that far-off coordinates keep their precision.
    const Vec2d o = ring.front();
    double twice = 0, cx = 0, cy = 0, mx = 0, my = 0;
    for (size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2d a{ring[i].x - o.x, ring[i].y - o.y};
        const Vec2d b{ring[(i + 1) % n].x - o.x, ring[(i + 1) % n].y - o.y};
        const double cross = a.x * b.y - b.x * a.y;
        twice += cross;
        cx += (a.x + b.x) * cross;
        cy += (a.y + b.y) * cross;
        mx += a.x;
        my += a.y;
    }
    if (std::abs(twice) < 1e-12) return {o.x + mx / double(ring.size()), o.y + my / double(ring.size())};
    return {o.x + cx / (3.0 * twice), o.y + cy / (3.0 * twice)};
}

bool contains(const Ring& ring, Vec2d p) {
    bool inside = false;
    for (size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
        const Vec2d a = ring[i], b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

bool contains(const Polygon& polygon, Vec2d p) {
    return contains(polygon.outer, p) &&
           std::none_of(polygon.holes.begin(), polygon.holes.end(), [p](const Ring& hole) { return contains(hole, p); });
}

void orient(Polygon& polygon) {
    if (signedArea(polygon.outer) < 0) std::reverse(polygon.outer.begin(), polygon.outer.end());
    for (Ring& hole : polygon.holes)
        if (signedArea(hole) > 0) std::reverse(hole.begin(), hole.end());
}

std::array<Vec2d, 2> bounds(const Ring& ring) {
    std::array<Vec2d, 2> box{Vec2d{HUGE_VAL, HUGE_VAL}, Vec2d{-HUGE_VAL, -HUGE_VAL}};
    for (const Vec2d p : ring) {
        box[0] = {std::min(box[0].x, p.x), std::min(box[0].y, p.y)};
        box[1] = {std::max(box[1].x, p.x), std::max(box[1].y, p.y)};
    }
    return box;
}

Vec2d nearestOnSegment(Vec2d p, Vec2d a, Vec2d b) {
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    const double t = length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
    return {a.x + t * dx, a.y + t * dy};
}

double distanceToSegment(Vec2d p, Vec2d a, Vec2d b) {
    const Vec2d q = nearestOnSegment(p, a, b);
    return std::hypot(p.x - q.x, p.y - q.y);
}

} // namespace urbis
