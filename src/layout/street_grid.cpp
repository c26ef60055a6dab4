#include "layout/street_grid.h"

#include "layout/river.h"
#include "math/hash.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace urbis {

namespace {

enum Axis : uint32_t { NorthSouth = 1, EastWest = 2 };

// Spacing in metres between consecutive centerlines: blocks are longer east-west.
constexpr float kSpacingX[2] = {100.0f, 140.0f};
constexpr float kSpacingY[2] = {62.0f, 88.0f};

// Chances per line, drawn from the seed and the line alone.
constexpr float kFourLaneAvenueChance = 0.6f;
constexpr float kOneWayChance = 0.25f;
constexpr float kSingleLaneChance = 0.5f;  // of a one-way street

GridLine lineClass(uint32_t seed, Axis axis, int k, int avenueEvery) {
    GridLine line;
    HashStream rng{hash3(hash2(seed, 0xc1a55u), axis, static_cast<uint32_t>(k))};
    if (k == 0) {
        line.profile = streetProfile(HighwayClass::Primary, 6);
    } else if (k % avenueEvery == 0) {
        line.profile = rng.uniform() < kFourLaneAvenueChance ? streetProfile(HighwayClass::Secondary, 4)
                                                             : streetProfile(HighwayClass::Tertiary, 2);
    } else if (rng.uniform() < kOneWayChance) {
        line.profile = streetProfile(HighwayClass::Residential, rng.uniform() < kSingleLaneChance ? 1 : 2, true);
        line.reversed = (k & 1) != 0;  // alternate directions, as in Manhattan
    } else {
        line.profile = streetProfile(HighwayClass::Residential, 2);
    }
    return line;
}

std::vector<GridLine> makeLines(uint32_t seed, int half, Axis axis) {
    const float* spacing = axis == NorthSouth ? kSpacingX : kSpacingY;
    const int avenueEvery = axis == NorthSouth ? 4 : 3;
    std::vector<GridLine> lines(static_cast<size_t>(2 * half + 1));
    auto at = [&](int k) -> GridLine& { return lines[static_cast<size_t>(k + half)]; };
    auto gap = [&](int k) {
        return static_cast<double>(spacing[0] + (spacing[1] - spacing[0]) *
                                                    hashToUnit(hash3(seed, axis, static_cast<uint32_t>(k))));
    };
    at(0) = lineClass(seed, axis, 0, avenueEvery);
    for (int k = 1; k <= half; ++k) {
        at(k) = lineClass(seed, axis, k, avenueEvery);
        at(k).position = at(k - 1).position + gap(k);
        at(-k) = lineClass(seed, axis, -k, avenueEvery);
        at(-k).position = at(-k + 1).position - gap(-k);
    }
    return lines;
}

bool nearLine(const std::vector<GridLine>& lines, double v) {
    auto it = std::lower_bound(lines.begin(), lines.end(), v,
                               [](const GridLine& l, double x) { return l.position < x; });
    if (it != lines.end() && it->position - v <= it->halfCorridor()) return true;
    return it != lines.begin() && v - (it - 1)->position <= (it - 1)->halfCorridor();
}

} // namespace

StreetGrid::StreetGrid(uint32_t seed, int half)
    : half_(half), xLines_(makeLines(seed, half, NorthSouth)), yLines_(makeLines(seed, half, EastWest)) {}

Rect2d StreetGrid::blockInterior(int i, int j) const {
    const GridLine &w = xLine(i), &e = xLine(i + 1), &s = yLine(j), &n = yLine(j + 1);
    return {w.position + w.halfCorridor(), s.position + s.halfCorridor(), e.position - e.halfCorridor(),
            n.position - n.halfCorridor()};
}

bool StreetGrid::onNorthSouthRoad(Vec2d p) const { return nearLine(xLines_, p.x); }

bool StreetGrid::onEastWestRoad(Vec2d p) const { return nearLine(yLines_, p.y); }

std::vector<Road> StreetGrid::roads(const std::vector<bool>& used, const GridSegmentFilter& keep) const {
    const int n = 2 * half_;
    auto isUsed = [&](int i, int j) {
        return i >= -half_ && i < half_ && j >= -half_ && j < half_ &&
               used[static_cast<size_t>((j + half_) * n + i + half_)];
    };
    std::vector<Road> out;
    // Along each line, a segment exists where a block on either side is used and `keep` agrees.
    auto emitRuns = [&](const GridLine& line, const std::vector<GridLine>& cross, auto segmentUsed, auto point) {
        Road road;
        for (int s = -half_; s <= half_; ++s) {
            bool on = s < half_ && segmentUsed(s);
            if (on && road.centerline.empty()) {
                road = line.profile.road();
                road.centerline.push_back(point(cross[static_cast<size_t>(s + half_)].position));
            }
            if (on) road.centerline.push_back(point(cross[static_cast<size_t>(s + 1 + half_)].position));
            if (!on && !road.centerline.empty()) {
                if (line.reversed) std::reverse(road.centerline.begin(), road.centerline.end());
                out.push_back(std::move(road));
                road.centerline.clear();
            }
        }
    };
    for (int k = -half_; k <= half_; ++k) {
        const GridLine& x = xLine(k);
        emitRuns(x, yLines_, [&](int j) { return (isUsed(k - 1, j) || isUsed(k, j)) && keep(true, k, j); },
                 [&](double y) { return Vec2d{x.position, y}; });
        const GridLine& y = yLine(k);
        emitRuns(y, xLines_, [&](int i) { return (isUsed(i, k - 1) || isUsed(i, k)) && keep(false, k, i); },
                 [&](double xv) { return Vec2d{xv, y.position}; });
    }
    return out;
}

namespace {

// Extra clearance in metres around arterials: covers the chords of the ring polyline and the
// snapping of their crossings onto the grid's junctions (arterial_junctions.cpp).
constexpr double kArterialMargin = 1.25;
// Steps in metres by which the ring's radius moves until it meets the diagonals away from the river.
constexpr double kRingRadiusStep = 20.0;
// Length in metres of one chord of the ring road.
constexpr double kRingChord = 10.0;

double crossWith(Vec2d d, Vec2d p) { return d.x * p.y - d.y * p.x; }

} // namespace

Arterials Arterials::generate(uint32_t seed, double cityRadius, const River& river) {
    Arterials a;
    HashStream rng{hash2(seed, 0xa27e41u)};
    if (cityRadius >= 700.0) {
        double angle = std::numbers::pi / 180.0 * rng.uniform(30.0f, 60.0f);
        for (int i = 0; i < 2; ++i) {
            a.diagonals.push_back({std::cos(angle), std::sin(angle)});
            angle += std::numbers::pi / 180.0 * rng.uniform(75.0f, 105.0f);
        }
    }
    if (cityRadius < 1500.0) return a;
    const double first = cityRadius * rng.uniform(0.45f, 0.6f);
    auto dry = [&](double radius) {
        for (Vec2d d : a.diagonals)
            for (double side : {-radius, radius})
                if (river.distance({side * d.x, side * d.y}) < kRiverJunctionClearance) return false;
        return true;
    };
    // Outward first, then inward; no ring if every radius in 0.4-0.7 of the city meets the river there.
    for (double r = first; r <= 0.7 * cityRadius && a.ringRadius == 0; r += kRingRadiusStep)
        if (dry(r)) a.ringRadius = r;
    for (double r = first - kRingRadiusStep; r >= 0.4 * cityRadius && a.ringRadius == 0; r -= kRingRadiusStep)
        if (dry(r)) a.ringRadius = r;
    return a;
}

bool Arterials::blocks(const Rect2d& r) const {
    const double hc = diagonal.halfCorridor() + kArterialMargin;
    const Vec2d corners[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
    for (Vec2d d : diagonals) {
        double lo = 1e300, hi = -1e300;
        for (Vec2d c : corners) {
            double s = crossWith(d, c);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        if (lo <= hc && hi >= -hc) return true;
    }
    if (ringRadius > 0) {
        const double rc = ring.halfCorridor() + kArterialMargin;
        double nx = std::clamp(0.0, r.x0, r.x1), ny = std::clamp(0.0, r.y0, r.y1);
        double fx = std::max(std::abs(r.x0), std::abs(r.x1)), fy = std::max(std::abs(r.y0), std::abs(r.y1));
        if (std::hypot(nx, ny) <= ringRadius + rc && std::hypot(fx, fy) >= ringRadius - rc) return true;
    }
    return false;
}

int Arterials::corridorsAt(Vec2d p) const {
    int n = 0;
    for (Vec2d d : diagonals) n += std::abs(crossWith(d, p)) <= diagonal.halfCorridor() ? 1 : 0;
    return n + (ringRadius > 0 && std::abs(std::hypot(p.x, p.y) - ringRadius) <= ring.halfCorridor() ? 1 : 0);
}

std::vector<Road> Arterials::roads(double cityRadius) const {
    std::vector<Road> out;
    for (Vec2d d : diagonals) {
        Road r = diagonal.road();
        r.centerline = {{-d.x * cityRadius, -d.y * cityRadius}, {d.x * cityRadius, d.y * cityRadius}};
        out.push_back(std::move(r));
    }
    if (ringRadius > 0 && ringRadius < cityRadius) {
        Road r = ring.road();
        const int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi * ringRadius / kRingChord));
        for (int i = 0; i <= n; ++i) {  // a closed way repeats its first vertex, as in OSM
            double t = 2.0 * std::numbers::pi * (i % n) / n;
            r.centerline.push_back({ringRadius * std::cos(t), ringRadius * std::sin(t)});
        }
        out.push_back(std::move(r));
    }
    return out;
}

} // namespace urbis
