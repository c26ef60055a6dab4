#include "streets/road_elevation.h"

#include "streets/bridge_segment_grid.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>

namespace urbis {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Edge {
    uint32_t to = 0;
    double length = 0;
    bool bridge = false;  ///< an edge of a bridge way
};

/// The ways' points merged into nodes, and the edges between consecutive points.
struct WayGraph {
    std::vector<std::vector<uint32_t>> nodeOf;  ///< per way, per point: its node
    std::vector<std::vector<Edge>> edges;       ///< per node
    std::vector<float> clearance;               ///< per node: the highest bridge clearance through it, 0 if none
    std::vector<uint8_t> onBridge, onGround;    ///< per node: a point of a bridge way / of a ground way
};

WayGraph buildGraph(const std::vector<ElevatedWay>& ways) {
    WayGraph g;
    std::unordered_map<PointKey, uint32_t, PointKeyHash> index;
    g.nodeOf.resize(ways.size());
    for (size_t w = 0; w < ways.size(); ++w) {
        const std::vector<Vec2d>& line = *ways[w].line;
        g.nodeOf[w].resize(line.size());
        for (size_t i = 0; i < line.size(); ++i) {
            const auto [it, added] = index.try_emplace(keyOf(line[i]), uint32_t(g.edges.size()));
            if (added) {
                g.edges.emplace_back();
                g.clearance.push_back(0.0f);
                g.onBridge.push_back(0);
                g.onGround.push_back(0);
            }
            const uint32_t node = it->second;
            g.nodeOf[w][i] = node;
            if (ways[w].bridge) {
                g.onBridge[node] = 1;
                g.clearance[node] = std::max(g.clearance[node], bridgeClearance(ways[w].layer));
            } else {
                g.onGround[node] = 1;
            }
        }
        for (size_t i = 1; i < line.size(); ++i) {
            const uint32_t a = g.nodeOf[w][i - 1], b = g.nodeOf[w][i];
            const double length = std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
            if (a == b || !std::isfinite(length)) continue;  // a repeated point, or a point at infinity
            g.edges[a].push_back({b, length, ways[w].bridge});
            g.edges[b].push_back({a, length, ways[w].bridge});
        }
    }
    return g;
}

/// Firmly on the ground: a ground way's junction or dead end (two ground edges only continue a way),
/// or a bridge's end where two or more ground ways meet.
bool isAnchor(const WayGraph& g, uint32_t node) {
    if (!g.onGround[node]) return false;
    size_t groundEdges = 0;
    for (const Edge& e : g.edges[node]) groundEdges += e.bridge ? 0 : 1;
    return g.onBridge[node] ? groundEdges >= 2 : groundEdges != 2;
}

using Entry = std::pair<double, uint32_t>;

/// Heights allowed by the anchors and wanted by the bridges: min over sources of cap + slope * distance.
std::vector<double> capHeights(const WayGraph& g) {
    const size_t n = g.edges.size();
    std::vector<double> height(n, kInfinity);
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (uint32_t v = 0; v < n; ++v) {
        if (isAnchor(g, v)) height[v] = 0.0;
        else if (g.onBridge[v]) height[v] = g.clearance[v];
        if (height[v] < kInfinity) queue.push({height[v], v});
    }
    while (!queue.empty()) {
        const auto [h, v] = queue.top();
        queue.pop();
        if (h > height[v]) continue;
        for (const Edge& e : g.edges[v]) {
            const double next = h + kMaxRampSlope * e.length;
            if (next < height[e.to]) {
                height[e.to] = next;
                queue.push({next, e.to});
            }
        }
    }
    return height;
}

/// The heights that `seeds` (a height per node, 0 for none) hold up: max over seeded nodes u of
/// seed(u) - slope * d(u, v), over the bridge ways' edges (`overBridges`) or the ground ways', never
/// raising nor passing a `pinned` node (none if empty); 0 where no seed is near.
std::vector<double> heldUp(const WayGraph& g, std::vector<double> height, bool overBridges,
                           const std::vector<uint8_t>& pinned) {
    std::priority_queue<Entry> queue;
    for (uint32_t v = 0; v < height.size(); ++v)
        if (height[v] > 0.0) queue.push({height[v], v});
    while (!queue.empty()) {
        const auto [h, v] = queue.top();
        queue.pop();
        if (h < height[v]) continue;
        for (const Edge& e : g.edges[v]) {
            const double next = h - kMaxRampSlope * e.length;
            if (e.bridge == overBridges && next > height[e.to] && (pinned.empty() || !pinned[e.to])) {
                height[e.to] = next;
                queue.push({next, e.to});
            }
        }
    }
    return height;
}

bool samePoint(Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; }

/// Whether two segments cross or touch (not where they share a point: ways meeting at a node).
bool segmentsCross(Vec2d p0, Vec2d p1, Vec2d q0, Vec2d q1) {
    if (samePoint(p0, q0) || samePoint(p0, q1) || samePoint(p1, q0) || samePoint(p1, q1)) return false;
    const double rx = p1.x - p0.x, ry = p1.y - p0.y, sx = q1.x - q0.x, sy = q1.y - q0.y;
    const double den = rx * sy - ry * sx;
    if (!(std::fabs(den) > 0.0)) return false;
    const double qx = q0.x - p0.x, qy = q0.y - p0.y;
    const double t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
    return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
}

/// Where bridges cross ground ways drawn at the surface in plan: per node, the clearance at which a
/// crossing bridge segment holds its two ends (0 where none crosses), and whether a ground segment
/// under a bridge ends there.
struct Crossings {
    std::vector<double> held;
    std::vector<uint8_t> under;
};

Crossings findCrossings(const std::vector<ElevatedWay>& ways, const WayGraph& g) {
    SegmentGrid ground;
    for (size_t w = 0; w < ways.size(); ++w)
        if (!ways[w].bridge && ways[w].surface) ground.add(*ways[w].line, 0.0, uint32_t(w), 0);
    Crossings c{std::vector<double>(g.edges.size(), 0.0), std::vector<uint8_t>(g.edges.size(), 0)};
    for (size_t w = 0; w < ways.size(); ++w) {
        if (!ways[w].bridge || !ways[w].surface) continue;
        const std::vector<Vec2d>& line = *ways[w].line;
        for (size_t i = 1; i < line.size(); ++i) {
            const Vec2d a = line[i - 1], b = line[i];
            const Vec2d lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
            for (const SegmentGrid::Segment* s : ground.near(lo, hi)) {
                if (!segmentsCross(a, b, s->a, s->b)) continue;
                for (uint32_t node : {g.nodeOf[w][i - 1], g.nodeOf[w][i]})
                    c.held[node] = std::max(c.held[node], double(bridgeClearance(ways[w].layer)));
                c.under[g.nodeOf[s->way][s->end - 1]] = 1;
                c.under[g.nodeOf[s->way][s->end]] = 1;
            }
        }
    }
    return c;
}

} // namespace

float bridgeClearance(int layer) { return layer == 0 ? 5.0f : 6.0f * float(std::max(layer, 1)); }

std::vector<std::vector<float>> wayElevations(const std::vector<ElevatedWay>& ways) {
    const WayGraph g = buildGraph(ways);
    const std::vector<double> cap = capHeights(g);
    Crossings crossings = findCrossings(ways, g);
    const std::vector<double> held = heldUp(g, std::move(crossings.held), true, {});
    // Both are kMaxRampSlope-Lipschitz along the bridges, so is their maximum; the approaches too,
    // except next to a ground way under a bridge, which stays on the ground (it would not pass under).
    std::vector<double> deck(g.edges.size(), 0.0);
    for (size_t v = 0; v < deck.size(); ++v)
        if (g.onBridge[v]) deck[v] = std::max(std::isfinite(cap[v]) ? cap[v] : 0.0, held[v]);
    const std::vector<double> height = heldUp(g, deck, false, crossings.under);
    std::vector<float> node(g.edges.size());
    for (size_t v = 0; v < node.size(); ++v) node[v] = float(std::max(height[v], 0.0));
    std::vector<std::vector<float>> out(ways.size());
    for (size_t w = 0; w < ways.size(); ++w)
        for (uint32_t v : g.nodeOf[w]) out[w].push_back(node[v]);
    return out;
}

std::vector<std::vector<float>> roadElevations(const std::vector<Road>& roads) {
    std::vector<ElevatedWay> ways;
    ways.reserve(roads.size());
    for (const Road& r : roads) ways.push_back({&r.centerline, r.bridge, r.layer, atSurface(r)});
    return wayElevations(ways);
}

std::vector<std::vector<float>> railwayElevations(const std::vector<Railway>& railways) {
    std::vector<ElevatedWay> ways;
    ways.reserve(railways.size());
    for (const Railway& r : railways) ways.push_back({&r.centerline, r.bridge, r.layer, atSurface(r)});
    return wayElevations(ways);
}

} // namespace urbis
