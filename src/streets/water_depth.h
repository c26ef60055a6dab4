// Where the water lies (host): its surface's level and its bed's depth, the two functions that put
// water on the ground, and the bed's mesh that they shape (docs/water.md).
#pragma once

#include "scene/triangle_mesh.h"
#include "streets/ground_cover_shapes.h"
#include "streets/water_options.h"

namespace urbis {

/// World y (m) of every water surface on the flat ground: kWaterLevel, above the ground cover. On a
/// terrain a water body's level is the lowest terrain along its shore (docs/water.md).
float waterSurfaceLevel();

/// Metres below the ground's plane (y = 0) of the bed at `distance` metres from the shore: a bank
/// falling as 1 - (1 - t)^2, t = distance / shelfWidth (steep at the shore, level at maxDepth), and
/// kMinBedDepth at least, so that the bed lies under the ground's plane even at the shore. On a
/// terrain the same profile below the water's level is carved into the terrain, its bed (carveWaterBeds).
float waterBedDepth(double distance, const WaterOptions& options);

/// The bed's depth at the shore, m below the ground's plane.
inline constexpr float kMinBedDepth = 0.05f;

/// Adds the bed of water `shape` to `mesh`: its triangles (trianglesNearBoundary, cells of half the
/// shelf near the shore) at -waterBedDepth of each vertex's distance to the shore. Returns the
/// triangles added (0 on failure).
size_t meshWaterBed(const CoverShapes& shapes, size_t shape, const WaterOptions& options, TriangleInfo info,
                    TriangleMesh& mesh);

} // namespace urbis
