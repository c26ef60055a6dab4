// Triangles of a BVH leaf packed four at a time, structure of arrays (host+device POD).
#pragma once

#include "scene/triangle.h"

#include <cstdint>

namespace urbis {

/// Triangles per TriangleBlock.
inline constexpr int kTriangleBlockWidth = 4;

/// Up to four triangles of one leaf, vertex coordinates structure of arrays (as Embree's Triangle4v),
/// so that the watertight test runs on the four lanes at once (geometry/triangle_block_sse.h). A leaf
/// of fewer triangles repeats its last one in the remaining lanes: a repeated lane hits at the same
/// distance as the lane it copies and loses the tie to it, so it never changes a hit.
/// 32-byte aligned: 160 bytes then always span three cache lines, not sometimes four.
struct alignas(32) TriangleBlock {
    float p[3][3][kTriangleBlockWidth];   ///< [vertex][axis][lane], world space, metres
    uint32_t prim[kTriangleBlockWidth];   ///< each lane's triangle: an index into the scene's triangles

    /// The triangle of lane `lane`.
    URBIS_HD Triangle triangle(int lane) const {
        return {{p[0][0][lane], p[0][1][lane], p[0][2][lane]},
                {p[1][0][lane], p[1][1][lane], p[1][2][lane]},
                {p[2][0][lane], p[2][1][lane], p[2][2][lane]}};
    }
};

static_assert(sizeof(TriangleBlock) == 160, "TriangleBlock is meant to be 160 bytes");

} // namespace urbis
