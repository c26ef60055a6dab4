// Which of a band's planes each flat area lies on, so that areas that overlap never share a plane
// (street_levels.h gives the bands: ground cover, paved areas).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace urbis {

/// Planes a band holds: those at `base + i * step` below `ceiling`, i = 0, 1, ...
int planesBetween(float base, float ceiling, float step);

/// The plane of each item, for items listed bottom first: one above the highest earlier item it
/// overlaps (`overlap(i, j)`, j < i), the lowest plane when it overlaps none. So an item lies above
/// every earlier one it overlaps, and the band needs as many planes as the deepest pile, not one per
/// item. -1 for an item whose plane would be `planes` or above: it is left out, and nothing rests on
/// it. Tests the earlier items from the highest plane down and stops at the first overlap, so a wide
/// area under many small ones is tested only by those that overlap nothing above it.
std::vector<int> stackPlanes(size_t items, int planes, const std::function<bool(size_t, size_t)>& overlap);

} // namespace urbis
