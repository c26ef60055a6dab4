// The city's trees into its mesh (host): placed (nature/tree_placement.h), made records or their
// triangle twin, with their materials after the mesh's and their objects after the streets'.
#pragma once

#include "citygen/city_mesher.h"

#include <cstdint>

namespace urbis {

/// Adds the trees of `city` to `out`: records in out.trees (geometry trees=procedural) or the twin's
/// triangles in out.mesh (trianglesByKind["trees"]), and the forest beyond the city to out.forests
/// (procedural in either mode: its trees are cells, not records); streetCounts["trees"] the trees made,
/// the forest's counted cell by cell; mapped trees left out go to out.dropped. Object ids from
/// `firstObject` up, one per tree, then one for the whole forest (the last id of TriangleInfo's 24
/// bits is shared beyond that).
void addCityTrees(const CityModel& city, const CityMeshOptions& options, uint32_t firstObject, CityMesh& out);

} // namespace urbis
