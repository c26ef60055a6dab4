// Road markings as geometry for an export (host): the bands urbis paints per ray
// (geometry/road_markings.h), each cut into its lines, dashes and stripes and laid on the road's own
// triangles a little above them, so that they follow the carriageway on a terrain or a bridge.
#pragma once

#include "scene/road_segment.h"
#include "scene/triangle_mesh.h"

#include <vector>

namespace urbis {

/// Metres the markings lie above the road surface: clear of it in a depth buffer seen from afar,
/// invisible from the street.
inline constexpr float kMarkingLift = 0.02f;

/// The markings of `segments` on the Road triangles of `mesh` (whose object indexes `segments`):
/// every rectangle of paint clipped to each triangle of its segment (in plan) and lifted kMarkingLift
/// along y, facing up. Material: RoadSegment::paint (white) or paint + 1 (yellow); object: the road's
/// object; part: Road. The same input gives the same triangles in the same order.
TriangleMesh roadMarkingMesh(const std::vector<RoadSegment>& segments, const TriangleMesh& mesh);

} // namespace urbis
