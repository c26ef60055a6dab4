// One building's geometry: a procedural wall record per ring edge large enough for a facade (a
// plain quad of stored triangles otherwise) up to the roof, the roof (citygen/roof_mesher.h) and a
// floor where the building floats above the ground, triangulated by GEOS's constrained Delaunay
// triangulation, so holes and concave footprints need no hand-written ear clipping.
#pragma once

#include "citygen/facade_layout.h"
#include "scene/triangle_mesh.h"
#include "model/city_model.h"

#include <geos_c.h>

#include <map>
#include <string>

namespace urbis {

/// City plane (x east, y north, metres) at height h to world (x east, y up, z south).
inline Vec3f worldFromCity(Vec2d p, double h) { return {float(p.x), float(h), float(-p.y)}; }

/// Triangle counts of one building by part, and its walls by representation.
struct BuildingTriangleCounts {
    size_t walls = 0, roofs = 0;
    std::map<std::string, uint64_t> roofFallbacks;  ///< roofs meshed as a simpler shape, by reason
    size_t wallRecords = 0;   ///< procedural walls
    size_t plainWalls = 0;    ///< walls too small for a facade (two triangles each)
    size_t holesDropped = 0;  ///< footprint holes cleanFootprint dropped
};

/// Appends the walls and caps of `building` over its cleaned footprint (citygen/footprint_cleaning.h):
/// plain walls and caps to `mesh`, walls with a facade (when `facade` is given; all plain when null)
/// to `walls`. Returns null, or, appending nothing, why the building cannot be meshed:
/// "degenerate_footprint" (nothing left after cleaning), "invalid_footprint" (not a valid polygon
/// for GEOS, which is then not asked to triangulate it), "triangulation_failed". `geos` is a
/// per-thread GEOS context.
const char* meshBuilding(GEOSContextHandle_t geos, const Building& building, TriangleInfo wallInfo, TriangleInfo roofInfo,
                  const WallContext* facade, TriangleMesh& mesh, std::vector<WallRecord>& walls,
                  BuildingTriangleCounts& counts);

} // namespace urbis
