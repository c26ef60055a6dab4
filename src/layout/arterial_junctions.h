// Junctions of the arterials with the grid and with each other: junctions are found from shared
// points, so every crossing of two generated roads must be a vertex of both, bit for bit.
#pragma once

#include "layout/street_grid.h"
#include "model/city_model.h"

#include <vector>

namespace urbis {

/// Inserts the point where an arterial crosses a grid road into both (the same Vec2d), and where
/// arterials cross each other into both. A crossing within 1 m of a grid junction moves onto it
/// (kArterialMargin in street_grid.cpp leaves room for that), so that three roads meet there
/// rather than a sliver of road between two junctions; the ring's own vertices within 1 m of a
/// junction go for the same reason. `arterialRoads` are `arterials.roads(...)`: the diagonals first.
void joinArterials(const StreetGrid& grid, const Arterials& arterials, std::vector<Road>& gridRoads,
                   std::vector<Road>& arterialRoads);

} // namespace urbis
