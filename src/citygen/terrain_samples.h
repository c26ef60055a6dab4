// The terrain's heights edited after it is built (host): the water's beds and the streets' grades
// lower or set samples, and the min/max hierarchy is rebuilt over the result.
#pragma once

#include "scene/terrain_field.h"

#include <vector>

namespace urbis {

/// The nx nz heights of `terrain`, without its hierarchy (row j at [j nx]).
std::vector<float> terrainHeights(const TerrainField& terrain);

/// Replaces `terrain`'s heights (nx nz, the same grid) and rebuilds its hierarchy and extremes; the
/// record's other fields (materials, march) stay.
void setTerrainHeights(TerrainField& terrain, std::vector<float> heights);

} // namespace urbis
