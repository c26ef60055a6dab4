#include "layout/bridges.h"

#include "layout/centerline_edit.h"
#include "math/hash.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace urbis {

namespace {

constexpr double kSampleStep = 1.0;    // m along a segment between tests for water
constexpr double kRate = 2.0;          // bound on how fast River::distance changes per metre along a road
constexpr double kReuseVertex = 0.5;   // m: an existing vertex this close ends the bridge instead
constexpr float kStreetBridgeChance = 0.5f;  // of a residential line

// Whether a centerline in `roads` crosses the north-south segment x = X, y in [y0, y1].
bool crossesVertical(const std::vector<Road>& roads, double x, double y0, double y1) {
    for (const Road& r : roads)
        for (size_t i = 0; i + 1 < r.centerline.size(); ++i) {
            const Vec2d a = r.centerline[i], b = r.centerline[i + 1];
            if ((a.x - x) * (b.x - x) > 0 || a.x == b.x) continue;
            const double y = a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y);
            if (y >= y0 && y <= y1) return true;
        }
    return false;
}

bool before(Spot a, Spot b) { return a.segment != b.segment ? a.segment < b.segment : a.offset < b.offset; }

// The stretches of `line` over water, as (from, to) spots, in order.
std::vector<std::pair<Spot, Spot>> wetStretches(const std::vector<Vec2d>& line, const River& river) {
    std::vector<std::pair<Spot, Spot>> out;
    bool wet = river.distance(line[0]) < 0;
    Spot from;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2d a = line[i], b = line[i + 1];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        auto at = [&](double t) { return Vec2d{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; };
        if (!wet && river.distance(a) + river.distance(b) > kRate * len) continue;  // dry all along
        const int steps = std::max(1, static_cast<int>(std::ceil(len / kSampleStep)));
        for (int k = 1; k <= steps; ++k) {
            double lo = double(k - 1) / steps, hi = double(k) / steps;
            if ((river.distance(at(hi)) < 0) == wet) continue;
            for (int n = 0; n < 40; ++n) {  // the edge, by bisection
                const double mid = 0.5 * (lo + hi);
                ((river.distance(at(mid)) < 0) == wet ? lo : hi) = mid;
            }
            const Spot edge{i, hi * len};
            if (wet) out.push_back({from, edge});
            else from = edge;
            wet = !wet;
        }
    }
    if (wet) out.push_back({from, Spot{line.size() - 2, std::hypot(line.back().x - line[line.size() - 2].x,
                                                                  line.back().y - line[line.size() - 2].y)}});
    return out;
}

} // namespace

GridSegmentFilter riverGridFilter(const StreetGrid& grid, const River& river, const std::vector<Road>& arterials,
                                  uint32_t seed) {
    const int half = grid.half();
    // Per north-south line: the stretch of y where it has no street, empty where it bridges the river.
    std::vector<std::pair<double, double>> gap(static_cast<size_t>(2 * half + 1));
    for (int k = -half; k <= half; ++k) {
        const GridLine& line = grid.xLine(k);
        auto [south, north] = river.across(line.position);
        south -= kRiverJunctionClearance;
        north += kRiverJunctionClearance;
        const bool street = line.profile.highway == HighwayClass::Residential;
        const bool bridged = (!street || hashToUnit(hash3(seed, 0xb1d6eu, static_cast<uint32_t>(k))) < kStreetBridgeChance) &&
                             !crossesVertical(arterials, line.position, south, north);
        gap[static_cast<size_t>(k + half)] = bridged ? std::pair{0.0, 0.0} : std::pair{south, north};
    }
    return [&grid, &river, gap = std::move(gap)](bool northSouth, int line, int segment) {
        if (northSouth) {
            const auto [south, north] = gap[static_cast<size_t>(line + grid.half())];
            return south == north || grid.yLine(segment + 1).position < south || grid.yLine(segment).position > north;
        }
        const double y = grid.yLine(line).position;
        return !river.near({grid.xLine(segment).position, y, grid.xLine(segment + 1).position, y},
                           kRiverJunctionClearance);
    };
}

void splitBridges(std::vector<Road>& roads, const River& river) {
    std::vector<Road> out;
    out.reserve(roads.size());
    for (Road& road : roads) {
        std::vector<std::pair<Spot, Spot>> spans;
        for (auto [wetFrom, wetTo] : wetStretches(road.centerline, river)) {
            const Spot from = advance(road.centerline, wetFrom, -kBridgeLanding);
            const Spot to = advance(road.centerline, wetTo, kBridgeLanding);
            if (!spans.empty() && !before(spans.back().second, from)) spans.back().second = to;
            else spans.push_back({from, to});
        }
        if (spans.empty()) {
            out.push_back(std::move(road));
            continue;
        }
        std::vector<Spot> cuts;
        for (auto [from, to] : spans) {
            cuts.push_back(from);
            cuts.push_back(to);
        }
        const CutCenterline cut = cutAt(road.centerline, cuts, kReuseVertex);
        auto piece = [&](size_t first, size_t last, bool bridge) {
            if (last <= first) return;
            Road r = road;
            r.centerline.assign(cut.points.begin() + static_cast<long>(first), cut.points.begin() + static_cast<long>(last) + 1);
            r.bridge = bridge;
            r.layer = bridge ? 1 : road.layer;
            out.push_back(std::move(r));
        };
        size_t start = 0;
        for (size_t k = 0; k < cuts.size(); k += 2) {
            piece(start, cut.vertexAt[k], false);
            piece(cut.vertexAt[k], cut.vertexAt[k + 1], true);
            start = cut.vertexAt[k + 1];
        }
        piece(start, cut.points.size() - 1, false);
    }
    roads = std::move(out);
}

} // namespace urbis
