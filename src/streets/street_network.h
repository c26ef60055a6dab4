// The road network as stored triangles: carriageways (with their markings' RoadSegment records),
// junction polygons, sidewalks with curbs, and paths, over the fitted roads (host).
#pragma once

#include "model/city_model.h"
#include "streets/street_mesh.h"

#include <vector>

namespace urbis {

/// Appends the network of `fitted` (fitRoads(city, ...)) to `out`: carriageways at kRoadLevel, one
/// RoadSegment per centerline segment (a Road triangle's object indexes out.roadSegments), junctions
/// where three or more carriageways meet (osm2streets' trimmed edges, shapeJunctions), mitres where
/// two do, square ends with a face at dead ends; sidewalks at kSidewalkLevel with a curb face along
/// the carriageway, a face down to the ground outside and round the junctions' corners; footways,
/// paths, cycleways and steps as flat paths (part Sidewalk, material by surface). Everything is lifted
/// by `elevations` (per fitted road, per centerline vertex, m above the ground; roadElevations, or
/// zeros). Zebras come from city.crossings on a segment's end vertex. Each fitted road is an object:
/// options.firstObject + out.objects + its index. Counts go to out.counts / trianglesByKind keyed
/// roads, junctions, sidewalks (paths among them), crossings. Deterministic.
void meshStreetNetwork(const CityModel& city, const std::vector<Road>& fitted,
                       const std::vector<std::vector<float>>& elevations, const StreetOptions& options,
                       StreetMesh& out);

} // namespace urbis
