// The footprint a building is meshed from: its walls, caps, roof and straight skeleton all use the
// one cleaned polygon, so the skeleton's contour points stay the walls' own points bit for bit.
#pragma once

#include "model/city_model.h"

#include <optional>

namespace urbis {

/// Points closer than this (m) are one point, and a point this close to the line through its
/// neighbours lies on it: OSM stores 1e-7 degrees, about 1.1 cm.
inline constexpr double kFootprintTolerance = 0.01;

/// What cleanFootprint made of a footprint.
struct CleanedFootprint {
    Polygon polygon;
    size_t holesDropped = 0;   ///< holes too small, degenerate, or touching the outer ring or another hole
};

/// `footprint` as CGAL's straight skeleton accepts it (CGAL 5.5 segfaults on a hole that touches
/// the outer ring, as GEOSMakeValid leaves a bow-tie, and on nearly collinear edges): rings without
/// points within kFootprintTolerance of the previous one or of the line through their neighbours
/// (repeated until none is left); the outer ring counter-clockwise, holes clockwise; holes left
/// with fewer than 3 points or under 0.01 m^2, or coming within kFootprintTolerance of the outer
/// ring or of an earlier hole, dropped. Kept points are the input's own. Nothing when the outer
/// ring keeps fewer than 3 points or no area, or a coordinate is not finite.
std::optional<CleanedFootprint> cleanFootprint(const Polygon& footprint);

} // namespace urbis
