// Triangulation of one simple polygon by ear clipping, by vertex index, so that the triangles reuse
// the polygon's own vertices (the faces of a straight skeleton; GEOS would return coordinates).
#pragma once

#include "model/city_model.h"

#include <array>
#include <cstdint>
#include <vector>

namespace urbis {

/// Triangles (index triples into `ring`) covering the simple polygon `ring` (either orientation).
/// An ear is a strictly convex corner whose triangle holds no other vertex, boundary included;
/// where none is left only collinear corners remain, and these are clipped as zero-area triangles,
/// which keeps every edge shared. O(n^3) worst case, meant for roof faces of tens of vertices.
/// Returns an empty list when the ring is not a simple polygon.
std::vector<std::array<uint32_t, 3>> earClip(const std::vector<Vec2d>& ring);

} // namespace urbis
