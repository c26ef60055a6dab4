// How high above the ground each vertex of a road or a railway lies: bridges are decks at a clearance
// by their `layer`, and every deck ramps down to the ground where it lands, at a bounded slope.
#pragma once

#include "model/city_model.h"
#include "streets/at_surface.h"

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

/// One centerline as the elevation sees it: its points, whether it is a bridge at some layer, and
/// whether it is drawn at the surface (a ground way that a bridge crossing it must clear).
struct ElevatedWay {
    const std::vector<Vec2d>* line = nullptr;
    bool bridge = false;
    int layer = 0;
    bool surface = true;
};

/// Per way, per centerline point: metres above the ground (0 on the ground). Ways meet where their
/// points are equal bit for bit, and every way through a point gets the same height there.
///
/// A bridge point lies at its clearance, lowered where a ground anchor is near:
///   cap(v) = min over sources u of (c(u) + kMaxRampSlope * d(u, v)),
/// c = 0 at anchors, the clearance at bridge points (a multi-source Dijkstra over all ways; d along
/// the ways). Anchors are points firmly on the ground: junctions and dead ends of ground ways, and a
/// bridge's end where two or more ground ways meet. Where a bridge crosses a ground way drawn at the
/// surface in plan, the segment over it is held at the clearance, and the deck comes down from there
/// no steeper than the slope (a Dijkstra of maxima over bridge ways): a bridge is never lower than the
/// road under it, even where its ends land on junctions (which then rise with it). A ground way that
/// continues a deck (its approach) ramps down from the deck's height at the same slope until it
/// reaches the ground (a Dijkstra of maxima over ground ways); a ground way under a bridge stays on
/// the ground where it passes under (the ramp next to it may be steeper there). Elsewhere the result
/// changes by at most kMaxRampSlope per metre along every way; consecutive bridge ways keep their
/// height across their shared points. O(n log n) in the number of points (crossings are found in a grid).
std::vector<std::vector<float>> wayElevations(const std::vector<ElevatedWay>& ways);

/// wayElevations of the roads (tunnels and underground ways count as ground ways not at the surface).
std::vector<std::vector<float>> roadElevations(const std::vector<Road>& roads);

/// wayElevations of the railways.
std::vector<std::vector<float>> railwayElevations(const std::vector<Railway>& railways);

} // namespace urbis
