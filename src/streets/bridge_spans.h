// Bridges as a terrain sees them: chains of bridge ways with their decks' elevations, so that on a
// terrain a deck can run straight between the ground at its two ends (citygen/bridges_on_terrain.h)
// instead of following the valley under it.
#pragma once

#include "model/city_model.h"

#include <vector>

namespace urbis {

/// One chain of bridge ways (joined where exactly two of their ends meet), in world x, z.
struct BridgeSpan {
    std::vector<Vec2d> line;       ///< world (x, z) per point, from one end of the chain to the other
    std::vector<float> elevation;  ///< m of the deck above flat ground per point (wayElevations)
    double halfWidth = 0;          ///< m from the centerline to the deck's farther edge
};

/// A bridge way: its centerline (local metres: x east, y north), elevations and half width.
struct BridgeWay {
    const std::vector<Vec2d>* line = nullptr;
    const std::vector<float>* elevation = nullptr;  ///< one per point of line
    double halfWidth = 0;
};

/// The chains of `ways`, each way in one chain, turned where the chain runs against it. A way ends a
/// chain at a point where any other than exactly one other bridge way ends; a ring starts anywhere.
std::vector<BridgeSpan> bridgeSpans(const std::vector<BridgeWay>& ways);

} // namespace urbis
