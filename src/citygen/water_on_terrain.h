// Water on a terrain (host): each water body of the meshed city at its own level, and the terrain as
// its bed, carved below that level under the water (docs/water.md § On a terrain).
#pragma once

#include "citygen/city_mesher.h"
#include "scene/terrain_field.h"
#include "streets/water_options.h"

#include <map>
#include <vector>

namespace urbis {

/// A water body's surface on a terrain: flat at `level`, or, for a river drawn from its line
/// (CityMesh::waterFlows), falling along it and never rising downstream.
struct WaterLevel {
    float level = 0;              ///< a flat body's height (m); a river's lowest
    std::vector<Vec2d> line;      ///< a river's centerline (world x, z) in its flow direction, a point
                                  ///< every half sample spacing; empty for flat water
    std::vector<float> heights;   ///< the river's surface at each point of line
    /// The surface's height (m) over world (x, z): the level, or the river's, linear between the points
    /// of its line, at the line's point nearest (x, z).
    float at(float x, float z) const;
};

/// Each water body's surface, by its object id.
using WaterLevels = std::map<uint32_t, WaterLevel>;

/// The surfaces of `mesh`'s water bodies (its triangles of a Water material), by object id.
std::map<uint32_t, std::vector<Triangle>> waterSurfacesOf(const CityMesh& mesh);

/// Each water body's surface on `terrain`. A river drawn from its line: the ground along the line,
/// every half sample spacing, made non-increasing in its flow direction (each point at most the one
/// before it). Other water lies flat: at its OSM `ele` where tagged (mesh.waterElevations: metres above
/// sea level, the DEM's datum); else at the lowest ground along its shore (the edges its surface's
/// triangles do not share), sampled every half sample spacing. Never below kWaterLevel, so that the
/// sea and water beyond the grid lie over the flat ground as they do without a terrain.
WaterLevels waterLevelsOn(const CityMesh& mesh, const TerrainField& terrain);

/// Lowers every sample of `terrain` to at most the surface of the nearest river drawn from its line
/// plus options.bankSlope times its distance from the water (a chamfer distance, within 8 % of the
/// Euclidean one): banks instead of walls where a river runs below the hills around it, and the
/// samples under the river at its surface at most; then rebuilds the hierarchy. Nothing without rivers.
void carveRiverBanks(TerrainField& terrain, const CityMesh& mesh, const WaterLevels& levels, const WaterOptions& options);

/// Lowers every sample of `terrain` under a water body to at most its surface there minus waterBedDepth of its
/// distance to the shore (the bank's profile; maxDepth a shelf from the shore), so that the terrain is
/// the bed and the shoreline is where it crosses the level; then rebuilds the hierarchy.
void carveWaterBeds(TerrainField& terrain, const CityMesh& mesh, const WaterLevels& levels, const WaterOptions& options);

} // namespace urbis
