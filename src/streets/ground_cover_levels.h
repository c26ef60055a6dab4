// Which of a band's planes each flat area lies on, so that areas that overlap never share a plane
// (street_levels.h gives the bands: ground cover, paved areas).
#pragma once

#include "streets/ground_cover_shapes.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace urbis {

/// Planes a band holds: those at `base + i * step` below `ceiling`, i = 0, 1, ...
int planesBetween(float base, float ceiling, float step);

/// The plane of each item, for items listed bottom first with their `boxes`: one above the highest
/// earlier item it overlaps (`overlap(i, j)`, j < i, asked only where the boxes overlap), the lowest
/// plane when it overlaps none. So an item lies above every earlier one it overlaps, and the band
/// needs as many planes as the deepest pile, not one per item. -1 for an item whose plane would be
/// `planes` or above: it is left out, and nothing rests on it. The earlier items near an item come
/// from a grid (model/cell_grid.h) and are asked from the highest plane down, stopping at the first
/// overlap: 20,000 areas take a fraction of a second, not the minutes of all pairs.
std::vector<int> stackPlanes(const std::vector<PlaneBox>& boxes, int planes,
                             const std::function<bool(size_t, size_t)>& overlap);

} // namespace urbis
