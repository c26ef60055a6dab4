// The triangle twin of a tree (host): the trunk and branches as prisms, the crown as a latitude-
// longitude mesh of its displaced surface, each vertex where a sphere trace from outside towards the
// crown's centre meets scene/tree_shape.h's distance function; same objects, parts and materials as
// the sphere-traced tree.
#pragma once

#include "scene/tree_record.h"
#include "scene/triangle_mesh.h"

#include <cstddef>

namespace urbis {

/// Sides of the trunk's and the branches' prisms, and the crown mesh's bands and segments: 16 + 48
/// + 2 * 10 * 16 - 2 * 16 = 352 triangles for a broadleaf tree, 304 for a conifer.
inline constexpr int kTreeTrunkSides = 8;
inline constexpr int kTreeBranchSides = 6;
inline constexpr int kTreeCrownBands = 10;
inline constexpr int kTreeCrownSegments = 16;

/// Appends the twin of `tree` to `mesh`; returns the triangles added.
size_t meshTree(const TreeRecord& tree, TriangleMesh& mesh);

} // namespace urbis
