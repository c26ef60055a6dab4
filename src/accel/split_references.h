// Early split clipping (host): a long triangle that lies across the axes, a street's sidewalk or
// curb on a diagonal grid, has a box far larger than itself, which widens every node above its leaf;
// it is given several references instead, each bounding one piece of it.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

#include <vector>

namespace urbis {

/// When a triangle is split: while a piece's box has more than `maxAreaRatio` times the piece's area
/// (half the box's surface area against the piece's one side) and its longest side exceeds `minExtent`
/// metres, into at most 2^maxDepth pieces. The defaults were the fastest on San Francisco's streets
/// with the fewest references (docs/accel_notes.md § Split references for street surfaces).
struct SplitOptions {
    float maxAreaRatio = 4.0f;
    float minExtent = 2.0f;
    int maxDepth = 3;
};

/// Boxes of pieces of the triangle (a, b, c) whose union covers it (world space): the box of each piece is cut at the
/// middle of its longest side and both halves clipped to the triangle, recursively (E. Ernst, G.
/// Greiner, "Early Split Clipping for Bounding Volume Hierarchies", 2007). Each box is widened by a
/// millimetre against the rounding of clipped points and kept within the triangle's own box. One box,
/// the triangle's, when it is not worth splitting. Appends to `out`.
void splitTriangleBounds(Vec3f a, Vec3f b, Vec3f c, const SplitOptions& options, std::vector<Bounds3f>& out);

} // namespace urbis
