// How high above the ground each vertex of a road or a railway lies: bridges are decks at a clearance
// by their `layer`, and every deck ramps down to the ground where it lands, at a bounded slope.
#pragma once

#include "model/city_model.h"

#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

namespace urbis {

/// A point's coordinates bit for bit: ways meet at equal points (shared OSM nodes).
struct PointKey {
    uint64_t x = 0, y = 0;
    bool operator==(const PointKey&) const = default;
};

inline PointKey keyOf(Vec2d p) { return {std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y)}; }

struct PointKeyHash {
    size_t operator()(const PointKey& k) const { return std::hash<uint64_t>()(k.x * 0x9E3779B97F4A7C15ull ^ k.y); }
};

/// Steepest ramp of a deck or its approach, rise over run (motorway design limits are 4-6 %).
inline constexpr double kMaxRampSlope = 0.06;

/// Metres a bridge's deck lies above the ground away from its ramps: layer 0 bridges (over water or a
/// railway) 5 m, layer 1 (and below) 6 m, each layer above 6 m more.
float bridgeClearance(int layer);

/// One centerline as the elevation sees it: its points, and whether it is a bridge at some layer.
struct ElevatedWay {
    const std::vector<Vec2d>* line = nullptr;
    bool bridge = false;
    int layer = 0;
};

/// Per way, per centerline point: metres above the ground (0 on the ground). Ways meet where their
/// points are equal bit for bit, and every way through a point gets the same height there.
///
/// A bridge point lies at its clearance, lowered where a ground anchor is near:
///   e(v) = min over sources u of (cap(u) + kMaxRampSlope * d(u, v)),
/// cap = 0 at anchors, the clearance at bridge points (a multi-source Dijkstra over all ways; d along
/// the ways). Anchors are points firmly on the ground: junctions and dead ends of ground ways, and a
/// bridge's end where two or more ground ways meet. A ground way that continues a bridge (its approach)
/// ramps down from the deck's height at the same slope until it reaches the ground (a second Dijkstra,
/// over ground ways only), never above what its anchors allow. The result changes by at most
/// kMaxRampSlope per metre along every way; consecutive bridge ways keep their height across their
/// shared points. O(n log n) in the number of points.
std::vector<std::vector<float>> wayElevations(const std::vector<ElevatedWay>& ways);

/// wayElevations of the roads (tunnels and underground ways count as ground ways: they are not drawn).
std::vector<std::vector<float>> roadElevations(const std::vector<Road>& roads);

/// wayElevations of the railways.
std::vector<std::vector<float>> railwayElevations(const std::vector<Railway>& railways);

} // namespace urbis
