// Stack-based traversal of the flat 4-wide BVH (host+device): the reference that the tests and
// urbis_bench compare the renderer's 8-wide BVH (src/accel/wide_bvh_traverse.h) with.
#pragma once

#include "accel/bvh_traverse.h"
#include "bvh4/node.h"
#include "math/ray.h"

#include <cfloat>
#include <cstdint>

#if URBIS_HAVE_SSE
#include <emmintrin.h>
#endif

namespace urbis {

/// Entries of the traversal stack: the build keeps the tree under 64 levels; a node that the
/// traversal goes on into pushes at most kBvhWidth - 1 entries, one that it leaves kBvhWidth.
inline constexpr int kBvhStackSize = 64 * (kBvhWidth - 1) + kBvhWidth;

/// Robust slab test of the ray against the kBvhWidth child boxes of a node: the exit
/// distance is scaled by 1 + 2 gamma(3) so that rounding never culls a box the ray touches.
/// See "Robust BVH Ray Traversal", T. Ize, JCGT 2(2), 2013. Writes the entry distance of
/// each lane and returns a bit mask of the lanes whose box overlaps [tmin, tmax].
/// On x86 CPUs the four lanes go through SSE; elsewhere (nvcc, other CPUs) through the
/// scalar loop, which computes the same values bit for bit (same operations, same order; a
/// difference times a number, which no build contracts).
URBIS_HD inline unsigned intersectLanes(const BvhNode& node, const BvhRay& r, float tmin, float tmax,
                                        float (&tEntry)[kBvhWidth]) {
    constexpr float kRobustScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
    const float* nearX = node.bounds[r.nearPlane[0]];
    const float* nearY = node.bounds[r.nearPlane[1]];
    const float* nearZ = node.bounds[r.nearPlane[2]];
    const float* farX = node.bounds[(r.nearPlane[0] + 3) % 6];
    const float* farY = node.bounds[(r.nearPlane[1] + 3) % 6];
    const float* farZ = node.bounds[(r.nearPlane[2] + 3) % 6];
#if URBIS_HAVE_SSE
    static_assert(kBvhWidth == 4, "the SSE path tests 4 lanes");
    const __m128 ox = _mm_set1_ps(r.origin[0]), oy = _mm_set1_ps(r.origin[1]), oz = _mm_set1_ps(r.origin[2]);
    const __m128 ix = _mm_set1_ps(r.invDir[0]), iy = _mm_set1_ps(r.invDir[1]), iz = _mm_set1_ps(r.invDir[2]);
    const __m128 scale = _mm_set1_ps(kRobustScale);
    const __m128 nx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(nearX), ox), ix);
    const __m128 ny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(nearY), oy), iy);
    const __m128 nz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(nearZ), oz), iz);
    const __m128 fx = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(farX), ox), ix), scale);
    const __m128 fy = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(farY), oy), iy), scale);
    const __m128 fz = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(farZ), oz), iz), scale);
    // _mm_max_ps(a, b) is a > b ? a : b, as in the scalar path.
    const __m128 t0 = _mm_max_ps(nz, _mm_max_ps(ny, _mm_max_ps(nx, _mm_set1_ps(tmin))));
    const __m128 t1 = _mm_min_ps(fz, _mm_min_ps(fy, _mm_min_ps(fx, _mm_set1_ps(tmax))));
    _mm_storeu_ps(tEntry, t0);
    return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(t0, t1)));
#else
    unsigned mask = 0;
    for (int l = 0; l < kBvhWidth; ++l) {
        const float nx = (nearX[l] - r.origin[0]) * r.invDir[0];
        const float ny = (nearY[l] - r.origin[1]) * r.invDir[1];
        const float nz = (nearZ[l] - r.origin[2]) * r.invDir[2];
        const float fx = (farX[l] - r.origin[0]) * r.invDir[0] * kRobustScale;
        const float fy = (farY[l] - r.origin[1]) * r.invDir[1] * kRobustScale;
        const float fz = (farZ[l] - r.origin[2]) * r.invDir[2] * kRobustScale;
        float t0 = nx > tmin ? nx : tmin;
        t0 = ny > t0 ? ny : t0;
        t0 = nz > t0 ? nz : t0;
        float t1 = fx < tmax ? fx : tmax;
        t1 = fy < t1 ? fy : t1;
        t1 = fz < t1 ? fz : t1;
        tEntry[l] = t0;
        mask |= (t0 <= t1 ? 1u : 0u) << l;
    }
    return mask;
#endif
}

/// Closest-hit or any-hit (`anyHit`) traversal of a BVH built by buildBvh, in world space.
/// intersect(uint32_t prim, Ray& ray, HitRecord& hit) -> bool tests one primitive (prim indexes leaf
/// order, i.e. positions in the build's primOrder); on a hit it fills hit and shrinks ray.tmax.
/// Leaves of a visited node are tested at once (shrinking ray.tmax early); interior children are
/// visited nearest first and skipped when they start beyond the closest hit so far; any-hit
/// queries return at the first hit. Returns whether anything was hit. No allocation; fixed-size
/// stack.
template <typename HitRecord, typename IntersectPrim>
URBIS_HD bool traverseBvh(const BvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                          IntersectPrim&& intersect) {
    constexpr uint32_t kNoNode = 0xffffffffu, kLaneBits = kBvhWidth - 1;
    struct Entry {
        uint32_t node;
        float tEntry;
    };
    Entry stack[kBvhStackSize];
    int top = 0;
    bool found = false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        float tEntry[kBvhWidth];
        const unsigned hitMask = intersectLanes(node, r, ray.tmin, ray.tmax, tEntry);
        for (int l = 0; l < kBvhWidth; ++l) {
            if (!(hitMask >> l & 1u)) continue;
            for (uint32_t i = 0; i < node.primCount[l]; ++i) {
                if (intersect(node.child[l] + i, ray, hit)) {
                    found = true;
                    if (anyHit) return true;
                }
            }
        }
        // Interior children still in reach, the nearest next and the others pushed farthest first, each
        // placed by its rank among keys of (entry distance, lane): a non-negative float's bits order as
        // the float, the lane takes the two lowest (and the stored distance loses them: it only culls,
        // so a few ulps less is safe).
        unsigned inner = 0;
        int queuedCount = 0;
        uint32_t key[kBvhWidth];
        for (int l = 0; l < kBvhWidth; ++l) {
            const bool inReach = hitMask >> l & 1u && tEntry[l] <= ray.tmax && node.primCount[l] == 0;
            inner |= (inReach ? 1u : 0u) << l;
            queuedCount += inReach ? 1 : 0;
            key[l] = inReach ? (__builtin_bit_cast(uint32_t, tEntry[l]) & ~kLaneBits) | uint32_t(l) : ~0u;
        }
        current = kNoNode;
        for (int l = 0; l < kBvhWidth; ++l) {
            if (!(inner >> l & 1u)) continue;
            int rank = 0;
            for (int m = 0; m < kBvhWidth; ++m) rank += int(key[m] < key[l]);
            if (rank == 0) current = node.child[l];
            else stack[top + queuedCount - 1 - rank] = {node.child[l], __builtin_bit_cast(float, key[l] & ~kLaneBits)};
        }
        top += queuedCount - (current != kNoNode ? 1 : 0);
        while (current == kNoNode && top > 0) {
            const Entry e = stack[--top];
            if (e.tEntry <= ray.tmax) current = e.node;
        }
        if (current == kNoNode) return found;
    }
}

} // namespace urbis
