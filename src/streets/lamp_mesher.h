// The triangle twin of a street lamp (host): the pieces of scene/lamp_pieces.h as stored triangles,
// with the same objects, parts and materials as the analytic lamp.
#pragma once

#include "scene/lamp_record.h"
#include "scene/triangle_mesh.h"

#include <cstddef>

namespace urbis {

/// Segments around a cone, a cylinder, a disc or a sphere's latitude, and a globe's latitude bands.
/// Rings are widened so each polygon has its circle's area (half its edge inside the circle, half
/// out): with 24 segments a twin's silhouette lies within 0.5 % of a radius of the analytic one.
inline constexpr int kLampRingSegments = 24;
inline constexpr int kLampSphereBands = 12;

/// Appends the twin of `lamp` to `mesh`; returns the triangles added.
size_t meshLamp(const LampRecord& lamp, TriangleMesh& mesh);

} // namespace urbis
