// The terrain the parameters describe, as the renderer's heightfield: the fBm landscape and the
// DEM (reprojected to the city's tangent plane) sampled on one grid, with the fBm detail below the
// DEM's resolution; then the hierarchy over it (scene/terrain_field.h).
#pragma once

#include "model/city_model.h"
#include "scene/material.h"
#include "scene/terrain_field.h"
#include "terrain/terrain_params.h"

#include <vector>

namespace urbis {

/// The terrain of `params` around world (cx, cz) (the city's centre): the fBm landscape `size`
/// metres a side there, and/or the DEM's extent on the tangent plane at `origin` (the city's; none:
/// the DEM's centre, where world (0, 0) then lies), plus a border of `fade` metres over which the
/// heights fall to 0. Heights below 0 (the ground plane and sea level around it) are raised to 0.
/// Its materials are `firstMaterial` on (terrainMaterials). InputError on a bad DEM or parameter.
TerrainField buildTerrain(const TerrainParams& params, const GeoOrigin& origin, float cx, float cz, uint32_t firstMaterial);

/// The terrain's materials in TerrainMaterial order: rock, grass, snow, sand.
std::vector<Material> terrainMaterials();

/// The march named `name` (one of kTerrainMarches); InputError otherwise.
TerrainMarch terrainMarchOf(const std::string& name);

} // namespace urbis
