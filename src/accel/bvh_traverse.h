// What every BVH traversal shares (host+device): the ray as the slab tests take it, and the warp vote
// that holds costly work back until a whole warp wants it (wide_bvh_traverse.h).
#pragma once

#include "math/ray.h"

#include <cfloat>
#include <cstdint>

namespace urbis {

/// What the slab test needs of a ray, computed once per ray.
struct BvhRay {
    float origin[3];
    float invDir[3];
    /// The row of a node's planes (lo.x, lo.y, lo.z, hi.x, hi.y, hi.z) with the entry plane per axis:
    /// lo (0..2) if the direction is positive, else hi (3..5).
    int nearPlane[3];

    /// 1/x, or ±FLT_MAX where |x| is so small that 1/x would overflow; keeps (plane - origin)
    /// * invDir free of NaN (0 * inf) for axis-parallel rays. Exact (urbis.h): it decides hits.
    URBIS_HD static float safeInverse(float x) {
        constexpr float tiny = 1.0f / FLT_MAX;
        if (x >= 0.0f && x <= tiny) return FLT_MAX;
        if (x < 0.0f && x >= -tiny) return -FLT_MAX;
        return exactDiv(1.0f, x);
    }

    URBIS_HD explicit BvhRay(const Ray& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = ray.origin[axis];
            invDir[axis] = safeInverse(ray.dir[axis]);
            nearPlane[axis] = invDir[axis] < 0.0f ? axis + 3 : axis;
        }
    }
};

/// Whether every lane of a warp that runs this together wants to do something costly now, so that
/// the costly code runs with all of them rather than a few at a time; on the CPU (a ray is its own
/// warp) whether this one does. Every lane that reaches the call must make it, wanting or not.
/// Half or a quarter of the lanes were measured too: all is fastest (docs/gpu_notes.md § Deferred wall tests).
URBIS_HD inline bool warpAll(bool wants) {
#if URBIS_GPU_CODE
    return __all_sync(__activemask(), wants);
#else
    return wants;
#endif
}

} // namespace urbis
