// Parks and plazas of the generated city: blocks given over to green or paved ground.
#pragma once

#include "layout/layout_geometry.h"
#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// A park on `block` (metres): its Park area, footpaths meeting at its centre (a paved cross from
/// the middle of each side; gravel diagonals from the corners in about half the parks), ending at
/// the surrounding sidewalks, and trees (about one per `areaPerTree` m^2) kept off the paths.
/// `key` seeds the diagonals and the trees.
void layOutPark(const Rect2d& block, uint32_t key, double areaPerTree, CityModel& city);

/// A paved square on `block` (metres): a Pedestrian area of sett or paving stones, seeded by `key`.
Area plazaOn(const Rect2d& block, uint32_t key);

} // namespace urbis
