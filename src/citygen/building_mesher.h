// One building's stored triangles: walls from every ring edge up to the roof, the roof
// (citygen/roof_mesher.h) and a floor where the building floats above the ground, triangulated by GEOS's constrained Delaunay
// triangulation, so holes and concave footprints need no hand-written ear clipping.
#pragma once

#include "citygen/triangle_mesh.h"
#include "model/city_model.h"

#include <geos_c.h>

#include <map>
#include <string>

namespace urbis {

/// City plane (x east, y north, metres) at height h to world (x east, y up, z south).
inline Vec3f worldFromCity(Vec2d p, double h) { return {float(p.x), float(h), float(-p.y)}; }

/// Triangle counts of one building by part.
struct BuildingTriangleCounts {
    size_t walls = 0, roofs = 0;
    std::map<std::string, uint64_t> roofFallbacks;  ///< roofs meshed as a simpler shape, by reason
};

/// Appends the walls and caps of `building` to `mesh`. Returns false (appending nothing) when GEOS
/// cannot triangulate the footprint. `geos` is a per-thread GEOS context.
bool meshBuilding(GEOSContextHandle_t geos, const Building& building, TriangleInfo wallInfo, TriangleInfo roofInfo,
                  TriangleMesh& mesh, BuildingTriangleCounts& counts);

} // namespace urbis
