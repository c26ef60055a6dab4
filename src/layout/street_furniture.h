// Trees along roads and in parks. (Street lamps are placed by streets/, for every city alike.)
#pragma once

#include "layout/layout_geometry.h"
#include "model/city_model.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Points beside `road`'s centerline every `spacing` metres of its length, starting half a
/// spacing in, `offset` metres to either side.
std::vector<Vec2d> pointsBeside(const Road& road, double spacing, double offset);

/// Trees scattered in a park (rectangle in metres), about one per `areaPerTree` square metres,
/// kept 2 m inside its edge; `key` seeds positions and sizes (height 6-14 m, crown 4-8 m).
void plantPark(const Rect2d& park, double areaPerTree, uint32_t key, std::vector<Tree>& out);

} // namespace urbis
