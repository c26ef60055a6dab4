#include "streets/road_elevation.h"

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

/// Heights a ground way needs to meet a deck: max over bridge points b of e(b) - slope * distance, over
/// ground edges only; <= 0 where no deck is near.
std::vector<double> approachHeights(const WayGraph& g, const std::vector<double>& deck) {
    const size_t n = g.edges.size();
    std::vector<double> height(n, 0.0);
    std::priority_queue<Entry> queue;
    for (uint32_t v = 0; v < n; ++v)
        if (g.onBridge[v] && deck[v] > 0.0) {
            height[v] = deck[v];
            queue.push({deck[v], v});
        }
    while (!queue.empty()) {
        const auto [h, v] = queue.top();
        queue.pop();
        if (h < height[v]) continue;
        for (const Edge& e : g.edges[v]) {
            const double next = h - kMaxRampSlope * e.length;
            if (!e.bridge && next > height[e.to]) {
                height[e.to] = next;
                queue.push({next, e.to});
            }
        }
    }
    return height;
}

} // namespace

float bridgeClearance(int layer) { return layer == 0 ? 5.0f : 6.0f * float(std::max(layer, 1)); }

std::vector<std::vector<float>> wayElevations(const std::vector<ElevatedWay>& ways) {
    const WayGraph g = buildGraph(ways);
    const std::vector<double> cap = capHeights(g);
    const std::vector<double> approach = approachHeights(g, cap);
    std::vector<float> node(g.edges.size());
    for (size_t v = 0; v < node.size(); ++v) {
        // cap is kMaxRampSlope-Lipschitz along every way, so an approach (a deck minus the slope times
        // the distance) never rises above what the anchors allow.
        const double h = g.onBridge[v] ? cap[v] : approach[v];
        node[v] = std::isfinite(h) ? float(std::max(h, 0.0)) : 0.0f;
    }
    std::vector<std::vector<float>> out(ways.size());
    for (size_t w = 0; w < ways.size(); ++w)
        for (uint32_t v : g.nodeOf[w]) out[w].push_back(node[v]);
    return out;
}

std::vector<std::vector<float>> roadElevations(const std::vector<Road>& roads) {
    std::vector<ElevatedWay> ways;
    ways.reserve(roads.size());
    for (const Road& r : roads) ways.push_back({&r.centerline, r.bridge, r.layer});
    return wayElevations(ways);
}

std::vector<std::vector<float>> railwayElevations(const std::vector<Railway>& railways) {
    std::vector<ElevatedWay> ways;
    ways.reserve(railways.size());
    for (const Railway& r : railways) ways.push_back({&r.centerline, r.bridge, r.layer});
    return wayElevations(ways);
}

} // namespace urbis
