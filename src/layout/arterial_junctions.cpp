#include "layout/arterial_junctions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace urbis {

namespace {

constexpr double kSnap = 1.0;  // m: a crossing this close to a grid junction (or a ring vertex) merges with it

// The grid roads along each line: position of the line -> indices of its roads.
using LineRoads = std::map<double, std::vector<size_t>>;

// Inserts p into the grid road of `lines` at `position` whose extent holds p's coordinate `along`
// (y on a north-south line); false if no road there holds it.
bool insertIntoGridRoad(std::vector<Road>& roads, const LineRoads& lines, double position, Vec2d p, bool northSouth) {
    auto it = lines.find(position);
    if (it == lines.end()) return false;
    auto coord = [&](Vec2d v) { return northSouth ? v.y : v.x; };
    const double c = coord(p);
    for (size_t r : it->second) {
        std::vector<Vec2d>& line = roads[r].centerline;
        const bool ascending = coord(line.front()) < coord(line.back());
        const double lo = std::min(coord(line.front()), coord(line.back()));
        const double hi = std::max(coord(line.front()), coord(line.back()));
        if (c < lo || c > hi) continue;
        auto before = [&](const Vec2d& v, double x) { return ascending ? coord(v) < x : coord(v) > x; };
        auto at = std::lower_bound(line.begin(), line.end(), c, before);
        if (at == line.end() || coord(*at) != c) line.insert(at, p);
        return true;
    }
    return false;
}

struct Event {
    double t;  // along the arterial's segment, 0 to 1
    Vec2d point;
};

// Crossings of segment a-b with the grid lines of one axis that carry a road there, inserted into
// those roads; each point moves onto the grid junction when one is within kSnap of the segment.
// A segment of a diagonal through (0, 0) in direction `diagonal` is crossed where the whole
// diagonal is, whatever its length, so that a larger city has the same points.
void crossLines(Vec2d a, Vec2d b, const Vec2d* diagonal, const std::vector<GridLine>& lines,
                const std::vector<GridLine>& across, bool northSouth, std::vector<Road>& gridRoads,
                const LineRoads& index, std::vector<Event>& events) {
    auto coord = [&](Vec2d v) { return northSouth ? v.x : v.y; };  // across the lines
    auto other = [&](Vec2d v) { return northSouth ? v.y : v.x; };  // along the lines
    const double ca = coord(a), cb = coord(b);
    const double lo = std::min(ca, cb), hi = std::max(ca, cb);
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (lo == hi || length == 0) return;
    const double slant = std::abs(cb - ca) / length;  // perpendicular distance per metre along the line
    auto first = std::lower_bound(lines.begin(), lines.end(), lo,
                                  [](const GridLine& l, double v) { return l.position < v; });
    for (auto line = first; line != lines.end() && line->position <= hi; ++line) {
        const double t = (line->position - ca) / (cb - ca);
        // At an end of the segment, the end itself: a vertex shared with the next segment.
        const double along = diagonal           ? line->position * (other(*diagonal) / coord(*diagonal))
                             : line->position == ca ? other(a)
                             : line->position == cb ? other(b)
                                                    : other(a) + t * (other(b) - other(a));
        auto near = std::lower_bound(across.begin(), across.end(), along,
                                     [](const GridLine& l, double v) { return l.position < v; });
        double snapped = along;
        for (auto j : {near, near - (near == across.begin() ? 0 : 1)})
            if (j != across.end() && std::abs(j->position - along) * slant < kSnap) snapped = j->position;
        const Vec2d p = northSouth ? Vec2d{line->position, snapped} : Vec2d{snapped, line->position};
        if (insertIntoGridRoad(gridRoads, index, line->position, p, northSouth)) events.push_back({t, p});
    }
}

bool same(Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; }

// The arterial's centerline with the events of each segment inserted; its own interior vertices
// within kSnap of an event go.
std::vector<Vec2d> withJunctions(const std::vector<Vec2d>& line, const std::vector<std::vector<Event>>& events) {
    std::vector<Vec2d> out;
    std::vector<bool> junction;
    auto push = [&](Vec2d p, bool isJunction) {
        if (!out.empty() && same(out.back(), p)) {
            junction.back() = junction.back() || isJunction;
            return;
        }
        out.push_back(p);
        junction.push_back(isJunction);
    };
    for (size_t i = 0; i < line.size(); ++i) {
        push(line[i], false);
        if (i + 1 < line.size())
            for (const Event& e : events[i]) push(e.point, true);
    }
    std::vector<Vec2d> kept;
    for (size_t i = 0; i < out.size(); ++i) {
        auto close = [&](size_t j) { return junction[j] && std::hypot(out[j].x - out[i].x, out[j].y - out[i].y) < kSnap; };
        const bool interior = i > 0 && i + 1 < out.size();
        if (interior && !junction[i] && (close(i - 1) || close(i + 1))) continue;
        kept.push_back(out[i]);
    }
    return kept;
}

double cross2(Vec2d a, Vec2d b) { return a.x * b.y - a.y * b.x; }

// Inserts every crossing of the centerlines of a and b into both: a point inside a segment of one
// becomes a vertex of it (the other's vertex when it crosses there).
void joinPair(Road& a, Road& b) {
    std::vector<std::pair<size_t, Vec2d>> onA, onB;  // (segment, point)
    for (size_t i = 0; i + 1 < a.centerline.size(); ++i) {
        const Vec2d p = a.centerline[i], r{a.centerline[i + 1].x - p.x, a.centerline[i + 1].y - p.y};
        for (size_t j = 0; j + 1 < b.centerline.size(); ++j) {
            const Vec2d q = b.centerline[j], s{b.centerline[j + 1].x - q.x, b.centerline[j + 1].y - q.y};
            const double denom = cross2(r, s);
            if (denom == 0) continue;
            const Vec2d qp{q.x - p.x, q.y - p.y};
            const double t = cross2(qp, s) / denom, u = cross2(qp, r) / denom;
            // Half-open, so that a crossing at a vertex counts once.
            if (t < 0 || t >= 1 || u < 0 || u >= 1 || (t == 0 && u == 0)) continue;
            const Vec2d x = t == 0 ? p : u == 0 ? q : Vec2d{p.x + t * r.x, p.y + t * r.y};
            if (t > 0) onA.push_back({i, x});
            if (u > 0) onB.push_back({j, x});
        }
    }
    auto insert = [](Road& road, std::vector<std::pair<size_t, Vec2d>>& at) {
        auto along = [&](size_t segment, Vec2d v) {
            const Vec2d s = road.centerline[segment];
            return std::hypot(v.x - s.x, v.y - s.y);
        };
        std::sort(at.begin(), at.end(), [&](const auto& x, const auto& y) {
            return x.first != y.first ? x.first > y.first : along(x.first, x.second) > along(y.first, y.second);
        });
        for (const auto& [segment, point] : at)  // from the back, so that indices stay valid
            road.centerline.insert(road.centerline.begin() + static_cast<long>(segment) + 1, point);
    };
    insert(a, onA);
    insert(b, onB);
}

} // namespace

void joinArterials(const StreetGrid& grid, const Arterials& arterials, std::vector<Road>& gridRoads,
                   std::vector<Road>& arterialRoads) {
    std::vector<GridLine> xs, ys;
    for (int k = -grid.half(); k <= grid.half(); ++k) {
        xs.push_back(grid.xLine(k));
        ys.push_back(grid.yLine(k));
    }
    LineRoads northSouth, eastWest;
    for (size_t r = 0; r < gridRoads.size(); ++r) {
        const std::vector<Vec2d>& c = gridRoads[r].centerline;
        if (c.front().x == c.back().x) northSouth[c.front().x].push_back(r);
        else eastWest[c.front().y].push_back(r);
    }
    for (size_t a = 0; a < arterialRoads.size(); ++a) {
        const std::vector<Vec2d>& line = arterialRoads[a].centerline;
        const Vec2d* diagonal = a < arterials.diagonals.size() ? &arterials.diagonals[a] : nullptr;
        std::vector<std::vector<Event>> events(line.size());
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            crossLines(line[i], line[i + 1], diagonal, xs, ys, true, gridRoads, northSouth, events[i]);
            crossLines(line[i], line[i + 1], diagonal, ys, xs, false, gridRoads, eastWest, events[i]);
            std::sort(events[i].begin(), events[i].end(), [](const Event& x, const Event& y) { return x.t < y.t; });
        }
        arterialRoads[a].centerline = withJunctions(line, events);
    }
    for (size_t a = 0; a < arterialRoads.size(); ++a)
        for (size_t b = a + 1; b < arterialRoads.size(); ++b) joinPair(arterialRoads[a], arterialRoads[b]);
}

} // namespace urbis
