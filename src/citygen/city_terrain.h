// The terrain a scene description asks for, built around a meshed city and the city placed on it.
#pragma once

#include "citygen/city_mesher.h"
#include "model/city_model.h"
#include "scene/terrain_field.h"
#include "terrain/terrain_params.h"

namespace urbis {

/// The terrain of `params` (none: an empty field) around `mesh`'s city (tangent plane at `origin`,
/// the import's), its materials appended to the mesh's (a DEM without fBm: grass is the city's
/// ground material) and the mesh placed on it
/// (placeCityOnTerrain), its water bodies at their levels over beds carved into the terrain with
/// `water`'s bank profile (citygen/water_on_terrain.h). InputError on a bad DEM or parameter.
TerrainField cityTerrainOf(const TerrainParams& params, const GeoOrigin& origin, CityMesh& mesh,
                           const WaterOptions& water = {});

} // namespace urbis
