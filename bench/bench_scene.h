// The triangles every accel benchmark traces: one function, so the scene source can change.
#pragma once

#include "scene/triangle.h"

#include <string>
#include <vector>

namespace urbis::bench {

/// The benchmark scene in world space (metres, y up): the San Francisco extract
/// (`URBIS_SHARED_DATA/sf_downtown_2023.osm.pbf`, or the file named by the environment variable
/// URBIS_BENCH_OSM) meshed by citygen as a mass model (plain walls, roofs), plus a ground quad over the city; without the file, a
/// generated city of 100,000 buildings. `description` says which.
std::vector<Triangle> benchTriangles(std::string& description);

} // namespace urbis::bench
