// The roads as they are drawn: only those at the surface, cut where a centerline runs through a
// building, split into the edges of the street graph where ways meet, with sidewalks resolved and
// the corridor (carriageway + sidewalks) narrowed until it overlaps no building (the thesis's rule),
// so never wider than the street between facing buildings.
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urbis {

/// Whether a road class is drawn as a flat path (footway, path, cycleway, steps): no carriageway,
/// no sidewalks, no markings; paths meet only each other in junctions.
bool isPath(HighwayClass highway);

/// The sidewalk width a class gets where `sidewalk` says there is one but no width is tagged, metres.
float defaultSidewalkWidth(HighwayClass highway);

/// The fitted roads of `city`: each is one edge of the street graph (it starts and ends where ways
/// meet, end, or were cut at a building), a copy of its way's Road with its own centerline and final
/// `width`, `sidewalkLeftWidth` / `sidewalkRightWidth` (0: none that side) and `sidewalk` (None, Left,
/// Right or Both, agreeing with the widths). Ways not drawn at the surface (tunnel, covered,
/// location=underground, layer < 0 off a bridge), areas, degenerate lines and pieces inside or
/// squeezed shut by buildings are counted in `dropped` by reason. Sidewalks come from the tags, else
/// by class in town; none on a side where a mapped `footway=sidewalk` runs alongside. Sidewalks
/// shrink first, then the carriageway down to a minimum; where even that would overlap a building
/// the piece is cut out. Linear in the ways (footprints are found through a grid); deterministic.
std::vector<Road> fitRoads(const CityModel& city, std::map<std::string, uint64_t>& dropped);

} // namespace urbis
