// The triangle twin of a procedural wall: the same parts the intersector makes on demand, emitted
// once as stored triangles (the thesis's comparison, and what an export writes) (host).
#pragma once

#include "scene/triangle_mesh.h"
#include "scene/wall_record.h"

namespace urbis {

/// Triangles meshWall appends for `wall`: two per quad, twelve per box, over the margins and every cell.
size_t wallTwinTriangleCount(const WallRecord& wall);

/// No lit-room palette: every lit room has FacadeMaterial::RoomLit.
inline constexpr uint32_t kNoLitRoomPalette = ~0u;

/// Appends every part of `wall` (margins and all floors x slots) as world-space triangles, each
/// tagged with the wall's object and the part's SurfacePart and material. With `litRoomPalette` (the
/// first material of citygen/lit_room_palette.h's palette) a lit room's parts take its window's entry.
void meshWall(const WallRecord& wall, TriangleMesh& mesh, uint32_t litRoomPalette = kNoLitRoomPalette);

} // namespace urbis
