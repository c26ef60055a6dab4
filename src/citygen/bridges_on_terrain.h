// Bridges on a terrain (host): a deck runs straight between the ground at its chain's two ends, and
// follows the ground under it only where that would leave it less than its flat-ground clearance
// (an overpass over a road, a deck over a rise). A valley bridge stays level; a deck on flat ground
// lies as it does without a terrain.
#pragma once

#include "streets/bridge_segment_grid.h"
#include "streets/bridge_spans.h"
#include "scene/terrain_field.h"

#include <optional>
#include <vector>

namespace urbis {

class BridgesOnTerrain {
public:
    BridgesOnTerrain(const std::vector<BridgeSpan>& spans, const TerrainField& terrain);

    /// How far a point of a bridge's structure at world (x, z), meshed on flat ground, rises: the chord
    /// between the deck's heights at its chain's ends, G(end) + e(end), at the point's arc length, less
    /// the deck's elevation e there; or the ground at (x, z) where that is higher. nullopt beyond every
    /// deck (over half its width from its centerline) and beyond its chain's ends: the point follows
    /// the ground.
    std::optional<float> liftAt(float x, float z) const;

private:
    struct Span {
        const BridgeSpan* span = nullptr;
        std::vector<double> arc;   ///< m along the chain to each point
        float deckStart = 0, deckEnd = 0;  ///< the deck's world height at the chain's ends
    };
    std::vector<Span> spans_;
    SegmentGrid grid_;
    const TerrainField& terrain_;
};

} // namespace urbis
