// The trees of a `natural=tree_row` way: one at each end and along it at a spacing (OSM maps a row
// as a line; its trees are placed as the row says).
#pragma once

#include "osm/raw_features.h"

#include <vector>

namespace urbis {

/// Points along `line` (lon/lat degrees) about `spacing` metres apart: its first point, then the
/// points that divide each leg into equal pieces of at most `spacing`, its last point included.
/// Metres per degree are those of a sphere of 6371 km at the leg's latitude (rows are short).
std::vector<LonLat> treeRowPoints(const GeoLine& line, double spacing);

} // namespace urbis
