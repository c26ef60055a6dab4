// The watertight test of a TriangleBlock's lanes one at a time (host+device): the reference that the
// SIMD test (triangle_block_sse.h) equals bit for bit, and what the GPU takes.
#pragma once

#include "geometry/triangle_intersect.h"
#include "scene/triangle_block.h"

namespace urbis {

/// Tests the lanes of a TriangleBlock in lane order with intersectTriangle (watertight, two-sided,
/// tmin < t < tmax), each against the tmax the lanes before it left: the nearest hit wins and equal
/// distances go to the lower lane, as when the block's triangles are tested one by one. On a hit sets
/// hit = {block.prim[lane], t, u, v}, shrinks ray.tmax to t and returns true.
struct TriangleBlockScalar {
    URBIS_HD static bool hit(const TriangleBlock& block, const WatertightRay& wr, Ray& ray, Hit& hit) {
        bool found = false;
        for (int l = 0; l < kTriangleBlockWidth; ++l) {
            float t, u, v;
            if (!intersectTriangle(block.triangle(l), ray, wr, t, u, v)) continue;
            hit = {block.prim[l], t, u, v};
            ray.tmax = t;
            found = true;
        }
        return found;
    }
};

} // namespace urbis
