// Water on a terrain (host): each water body of the meshed city at its own level, and the terrain as
// its bed, carved below that level under the water (docs/water.md § On a terrain).
#pragma once

#include "citygen/city_mesher.h"
#include "scene/terrain_field.h"
#include "streets/water_options.h"

#include <map>
#include <vector>

namespace urbis {

/// The world height (m) of each water body's surface, by its object id.
using WaterLevels = std::map<uint32_t, float>;

/// The surfaces of `mesh`'s water bodies (its triangles of a Water material), by object id.
std::map<uint32_t, std::vector<Triangle>> waterSurfacesOf(const CityMesh& mesh);

/// Each water body's level on `terrain`: its OSM `ele` where tagged (mesh.waterElevations: metres above
/// sea level, the DEM's datum); else the lowest ground along its shore (the edges its surface's
/// triangles do not share), sampled every half sample spacing, never below kWaterLevel, so that the sea
/// and water beyond the grid lie over the flat ground as they do without a terrain.
WaterLevels waterLevelsOn(const CityMesh& mesh, const TerrainField& terrain);

/// Lowers every sample of `terrain` under a water body to at most its level minus waterBedDepth of its
/// distance to the shore (the bank's profile; maxDepth a shelf from the shore), so that the terrain is
/// the bed and the shoreline is where it crosses the level; then rebuilds the hierarchy.
void carveWaterBeds(TerrainField& terrain, const CityMesh& mesh, const WaterLevels& levels, const WaterOptions& options);

} // namespace urbis
