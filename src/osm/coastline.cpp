#include "osm/coastline.h"

#include "model/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace urbis {

namespace {

using Line = std::vector<Vec2d>;

bool same(Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; }

/// A chain's end farther than this (m) from every edge of the box lies inside it: the coastline broke off.
constexpr double kOnEdge = 1e-3;

/// Ways joined end to end, with their ids.
struct Chain {
    Line points;
    std::vector<int64_t> ids;
    bool closed() const { return points.size() >= 4 && same(points.front(), points.back()); }
};

/// The box and positions along its edge, counter-clockwise from its south-west corner.
struct EdgeBox {
    Vec2d lo, hi;
    double width() const { return hi.x - lo.x; }
    double height() const { return hi.y - lo.y; }
    double perimeter() const { return 2.0 * (width() + height()); }
    bool inside(Vec2d p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
    /// Distance from p (inside) to the nearest edge, and that edge's index (0 south, 1 east, 2 north, 3 west).
    double toEdge(Vec2d p, int& edge) const {
        const double d[4] = {p.y - lo.y, hi.x - p.x, hi.y - p.y, p.x - lo.x};
        edge = int(std::min_element(d, d + 4) - d);
        return d[edge];
    }
    Vec2d onEdge(Vec2d p) const {
        int edge;
        toEdge(p, edge);
        if (edge == 0) return {p.x, lo.y};
        if (edge == 1) return {hi.x, p.y};
        if (edge == 2) return {p.x, hi.y};
        return {lo.x, p.y};
    }
    /// Position along the edge of a point on it (the nearest edge's).
    double along(Vec2d p) const {
        int edge;
        toEdge(p, edge);
        if (edge == 0) return p.x - lo.x;
        if (edge == 1) return width() + (p.y - lo.y);
        if (edge == 2) return width() + height() + (hi.x - p.x);
        return 2.0 * width() + height() + (hi.y - p.y);
    }
    Vec2d corner(int k) const { return k == 0 ? lo : k == 1 ? Vec2d{hi.x, lo.y} : k == 2 ? hi : Vec2d{lo.x, hi.y}; }
    double cornerAlong(int k) const { return k == 0 ? 0.0 : k == 1 ? width() : k == 2 ? width() + height() : 2.0 * width() + height(); }
    /// Counter-clockwise distance along the edge from position a to position b.
    double ccw(double a, double b) const {
        const double d = std::fmod(b - a, perimeter());
        return d < 0 ? d + perimeter() : d;
    }
};

/// Joins the ways into chains wherever one's last point is another's first.
std::vector<Chain> joinChains(const std::vector<CoastlineWay>& ways) {
    std::map<std::pair<double, double>, std::vector<size_t>> byStart, byEnd;
    auto key = [](Vec2d p) { return std::make_pair(p.x, p.y); };
    for (size_t i = 0; i < ways.size(); ++i)
        if (ways[i].points.size() >= 2) {
            byStart[key(ways[i].points.front())].push_back(i);
            byEnd[key(ways[i].points.back())].push_back(i);
        }
    std::vector<bool> used(ways.size(), false);
    auto take = [&](const std::vector<size_t>* candidates) -> size_t {
        if (candidates)
            for (const size_t j : *candidates)
                if (!used[j]) return used[j] = true, j;
        return ways.size();
    };
    std::vector<Chain> chains;
    for (size_t i = 0; i < ways.size(); ++i) {
        if (used[i] || ways[i].points.size() < 2) continue;
        used[i] = true;
        Chain c{ways[i].points, {ways[i].osmId}};
        while (!c.closed()) {
            const auto it = byStart.find(key(c.points.back()));
            const size_t j = take(it == byStart.end() ? nullptr : &it->second);
            if (j == ways.size()) break;
            c.points.insert(c.points.end(), ways[j].points.begin() + 1, ways[j].points.end());
            c.ids.push_back(ways[j].osmId);
        }
        while (!c.closed()) {
            const auto it = byEnd.find(key(c.points.front()));
            const size_t j = take(it == byEnd.end() ? nullptr : &it->second);
            if (j == ways.size()) break;
            c.points.insert(c.points.begin(), ways[j].points.begin(), ways[j].points.end() - 1);
            c.ids.insert(c.ids.begin(), ways[j].osmId);
        }
        chains.push_back(std::move(c));
    }
    return chains;
}

/// The part of segment a-b inside the box (Liang and Barsky 1984): false when none, else the
/// parameters t0 <= t1 in [0, 1] of its ends.
bool clipSegment(Vec2d a, Vec2d b, const EdgeBox& box, double& t0, double& t1) {
    t0 = 0.0;
    t1 = 1.0;
    const double d[2] = {b.x - a.x, b.y - a.y}, start[2] = {a.x, a.y}, lo[2] = {box.lo.x, box.lo.y}, hi[2] = {box.hi.x, box.hi.y};
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0.0) {
            if (start[axis] < lo[axis] || start[axis] > hi[axis]) return false;
            continue;
        }
        double ta = (lo[axis] - start[axis]) / d[axis], tb = (hi[axis] - start[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

Vec2d lerp(Vec2d a, Vec2d b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

/// The pieces of an open line inside the box, in order.
std::vector<Line> clipLine(const Line& line, const EdgeBox& box) {
    std::vector<Line> pieces;
    Line current;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        double t0, t1;
        if (!clipSegment(line[i], line[i + 1], box, t0, t1)) {
            if (current.size() >= 2) pieces.push_back(current);
            current.clear();
            continue;
        }
        const Vec2d p0 = t0 == 0.0 ? line[i] : lerp(line[i], line[i + 1], t0);
        const Vec2d p1 = t1 == 1.0 ? line[i + 1] : lerp(line[i], line[i + 1], t1);
        if (current.empty()) current.push_back(p0);
        if (!same(current.back(), p1)) current.push_back(p1);
        if (t1 < 1.0) {
            if (current.size() >= 2) pieces.push_back(current);
            current.clear();
        }
    }
    if (current.size() >= 2) pieces.push_back(current);
    return pieces;
}

std::string wayNames(const std::vector<int64_t>& ids) {
    std::string names;
    for (size_t i = 0; i < ids.size() && i < 3; ++i) names += (i ? ", w" : "w") + std::to_string(ids[i]);
    if (ids.size() > 3) names += " and " + std::to_string(ids.size() - 3) + " more";
    return names;
}

/// A piece of coastline inside the box, from edge to edge, with the chain it came from.
struct Piece {
    Line points;
    size_t chain = 0;
};

} // namespace

SeaPolygons seaPolygons(const std::vector<CoastlineWay>& ways, Vec2d boxMin, Vec2d boxMax) {
    SeaPolygons out;
    const EdgeBox box{boxMin, boxMax};
    if (!(box.width() > 0 && box.height() > 0)) return out;
    const std::vector<Chain> chains = joinChains(ways);
    std::vector<Piece> pieces;
    std::vector<Ring> islands, inlandSeas;
    for (size_t c = 0; c < chains.size(); ++c) {
        Line line = chains[c].points;
        if (chains[c].closed()) {
            if (std::all_of(line.begin(), line.end(), [&](Vec2d p) { return box.inside(p); })) {
                Ring ring(line.begin(), line.end() - 1);
                (signedArea(ring) > 0 ? islands : inlandSeas).push_back(std::move(ring));
                continue;
            }
            // Start where the ring is outside, so that clipping cuts it only at the box.
            const auto outside = std::find_if(line.begin(), line.end() - 1, [&](Vec2d p) { return !box.inside(p); });
            Line rotated(outside, line.end() - 1);
            rotated.insert(rotated.end(), line.begin(), outside + 1);
            line = std::move(rotated);
        } else {
            // A chain that ends inside the box broke off there (a truncated extract, a gap in the
            // data): carried straight to the nearest edge, the most a single line can say.
            int edge;
            bool extended = false;
            for (const bool atEnd : {false, true}) {
                const Vec2d p = atEnd ? line.back() : line.front();
                if (!box.inside(p)) continue;
                const double distance = box.toEdge(p, edge);
                if (distance <= kOnEdge) continue;
                if (atEnd) line.push_back(box.onEdge(p));
                else line.insert(line.begin(), box.onEdge(p));
                char message[256];
                std::snprintf(message, sizeof message,
                              "natural=coastline %s %s inside the box, %.0f m from its edge: carried straight to the edge",
                              wayNames(chains[c].ids).c_str(), atEnd ? "ends" : "starts", distance);
                out.warnings.push_back(message);
                extended = true;
            }
            if (extended) out.extendedWays.insert(out.extendedWays.end(), chains[c].ids.begin(), chains[c].ids.end());
        }
        for (Line& piece : clipLine(line, box)) {
            std::reverse(piece.begin(), piece.end());   // the sea on the left
            pieces.push_back({std::move(piece), c});
        }
    }

    std::vector<Polygon> seas;
    std::vector<bool> visited(pieces.size(), false);
    for (size_t first = 0; first < pieces.size(); ++first) {
        if (visited[first]) continue;
        Ring ring;
        std::vector<size_t> walked;
        bool closed = false;
        for (size_t current = first;;) {
            visited[current] = true;
            walked.push_back(current);
            for (const Vec2d p : pieces[current].points)
                if (ring.empty() || !same(ring.back(), p)) ring.push_back(p);
            const double exit = box.along(pieces[current].points.back());
            size_t next = pieces.size();
            double nearest = HUGE_VAL;
            for (size_t q = 0; q < pieces.size(); ++q) {
                const double d = box.ccw(exit, box.along(pieces[q].points.front()));
                if (d < nearest) nearest = d, next = q;
            }
            int corners[4] = {0, 1, 2, 3};
            std::sort(corners, corners + 4, [&](int a, int b) { return box.ccw(exit, box.cornerAlong(a)) < box.ccw(exit, box.cornerAlong(b)); });
            for (const int k : corners) {
                const double d = box.ccw(exit, box.cornerAlong(k));
                if (d > 0 && d < nearest) ring.push_back(box.corner(k));
            }
            if (next == first) {
                closed = true;
                break;
            }
            if (visited[next]) break;   // pieces that cross or run the wrong way: no ring closes
            current = next;
        }
        if (!closed) {
            std::vector<int64_t> ids;
            for (const size_t p : walked) ids.insert(ids.end(), chains[pieces[p].chain].ids.begin(), chains[pieces[p].chain].ids.end());
            out.warnings.push_back("natural=coastline " + wayNames(ids) +
                                   ": pieces that do not close into a sea with the box's edge (crossing, or running the wrong way): left out");
            out.droppedWays.insert(out.droppedWays.end(), ids.begin(), ids.end());
            continue;
        }
        if (ring.size() >= 2 && same(ring.front(), ring.back())) ring.pop_back();
        if (ring.size() >= 3) seas.push_back({std::move(ring), {}});
    }

    if (pieces.empty() && !islands.empty()) {
        // No coastline crosses the box: it lies all in the sea if the outermost ring is an island.
        double largestIsland = 0, largestSea = 0;
        for (const Ring& r : islands) largestIsland = std::max(largestIsland, std::fabs(signedArea(r)));
        for (const Ring& r : inlandSeas) largestSea = std::max(largestSea, std::fabs(signedArea(r)));
        if (largestIsland > largestSea) seas.push_back({{box.corner(0), box.corner(1), box.corner(2), box.corner(3)}, {}});
    }
    for (Ring& r : inlandSeas) {
        std::reverse(r.begin(), r.end());
        seas.push_back({std::move(r), {}});
    }
    for (Ring& island : islands)
        for (Polygon& sea : seas)
            if (contains(sea.outer, island.front())) {
                std::reverse(island.begin(), island.end());
                sea.holes.push_back(std::move(island));
                break;
            }
    out.sea = std::move(seas);
    return out;
}

} // namespace urbis
