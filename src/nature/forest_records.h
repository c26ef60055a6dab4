// The forest beyond the city (host): the ForestRecords of a ring of forest around the city's extent,
// and how many trees a forest holds (the stats' count, cell by cell, as the renderer finds them).
#pragma once

#include "model/city_model.h"
#include "nature/tree_options.h"
#include "scene/forest_record.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// The ForestRecord of the forest that `options` fill into [x0, x1) x [z0, z1) (world metres) on flat
/// ground at height 0: cells of outerForestCell metres, each with a tree at outerForestDensity
/// (at most one a cell), the trees as filled-in trees grow (defaultHeight, sizeVariation, coniferShare,
/// season), their reach and top from the largest tree the variation allows. `object` for every tree;
/// `firstMaterial`: treeMaterials' first.
ForestRecord forestRecordOf(float x0, float z0, float x1, float z1, const TreeOptions& options, uint32_t object,
                            uint32_t firstMaterial);

/// The ring of options.outerForest metres of forest around the city's extent (the box of its
/// buildings, roads and areas, grown by its widest road's half width, a sidewalk and the clearance), as
/// four strips (south, north, west, east) of one seeded field of cells, so the ring has no seam. Empty
/// when the option is 0, trees are off or the city is empty.
std::vector<ForestRecord> outerForestRecords(const CityModel& city, const TreeOptions& options, uint32_t object,
                                             uint32_t firstMaterial);

/// The trees `forest` holds: its cells visited one by one (the stats' `trees` count).
uint64_t forestTreeCount(const ForestRecord& forest);

} // namespace urbis
