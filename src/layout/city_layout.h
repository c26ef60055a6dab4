// The generated city: a seeded procedural CityModel without OSM, from a village to a
// metropolis of millions of buildings. Produces the same records as the OSM importer.
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

struct LayoutParams {
    uint64_t buildings = 400;  ///< target building count, 1 to kMaxGeneratedBuildings
    uint32_t seed = 1;
    /// Building heights in metres (roof included), taller toward the centre within this range.
    float minBuildingHeight = 8.0f, maxBuildingHeight = 120.0f;
};

/// The largest building count generateCity accepts (about 2.5 GB of CityModel).
inline constexpr uint64_t kMaxGeneratedBuildings = 10'000'000;

/// A seeded procedural city in local metres (x east, y north) centred on (0, 0): a perturbed
/// grid of avenues and streets with diagonal and ring arterials, every road with the class,
/// lanes, widths, sidewalks and surface an OSM import would give it and a vertex at every
/// junction; pedestrian crossings near junctions; a river with bridges; blocks split into lots
/// along their frontage, footprints (rectangle, L, T, U, courtyard) on the lots, heights falling
/// off from the centre; parks with paths, plazas and trees. Street lamps are left to streets/,
/// which places them on every city alike. Blocks are filled from the centre outward until exactly
/// `params.buildings` buildings exist. Deterministic: the same params give an identical CityModel.
/// Throws InputError on impossible parameters (no buildings, more than kMaxGeneratedBuildings, a
/// non-positive or non-finite height, min above max).
CityModel generateCity(const LayoutParams& params);

} // namespace urbis
