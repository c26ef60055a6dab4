// Bridges of the generated city: where a road crosses the river.
#pragma once

#include "layout/river.h"
#include "layout/street_grid.h"
#include "model/city_model.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// How far in metres along the road a bridge reaches beyond the water onto each bank.
inline constexpr double kBridgeLanding = 15.0;

/// Which grid segments the river leaves: east-west ones within kRiverJunctionClearance of the
/// water go, so that no junction comes near a bridge; north-south ones cross it as bridges on
/// the main axis, the avenues and about half the streets (seeded by line), unless an arterial
/// crosses the line near the water; the others stop kRiverJunctionClearance short of it.
GridSegmentFilter riverGridFilter(const StreetGrid& grid, const River& river, const std::vector<Road>& arterials,
                                  uint32_t seed);

/// Splits every road that crosses the water into an approach, a bridge (bridge=true, layer 1)
/// spanning the water plus kBridgeLanding onto each bank, and an approach: ways in order, each
/// ending where the next starts (the same point). Crossings closer than two landings merge into
/// one bridge.
void splitBridges(std::vector<Road>& roads, const River& river);

} // namespace urbis
