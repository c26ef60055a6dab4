// Road bridges' structure: each bridge way's deck slab (sides and underside), parapets, abutments and
// piers, and the walls of its ramped approaches. The deck's top (carriageway, sidewalks) is meshed
// with the other roads, lifted by the same elevations.
#pragma once

#include "streets/street_mesh.h"

#include <vector>

namespace urbis {

/// Meshes the structure of every bridge road at `elevations` (roadElevations of `roads`), its deck as
/// wide as its carriageway (Road::width) plus its sidewalks (sidewalkLeftWidth, sidewalkRightWidth),
/// and embankment walls under the lifted parts of ground roads (approaches). Object id: the road's,
/// options.firstObject + its index (out.objects covers every road's). Adds `bridges` to out.counts
/// and their triangles (approaches included) to out.trianglesByKind["bridges"]; degenerate bridges
/// to out.dropped.
void meshBridges(const std::vector<Road>& roads, const std::vector<std::vector<float>>& elevations,
                 const StreetOptions& options, StreetMesh& out);

} // namespace urbis
