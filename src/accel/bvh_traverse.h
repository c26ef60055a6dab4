// Stack-based traversal of a flat 4-wide BVH (host+device).
#pragma once

#include "accel/bvh_node.h"
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

/// What the slab test needs of a ray, computed once per ray.
struct BvhRay {
    float origin[3];
    float invDir[3];
    int nearPlane[3];   ///< row of BvhNode::bounds with the entry plane per axis: lo (0..2) if the direction is positive, else hi (3..5)

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

/// Sorts four keys in ascending order (a network of five compare-exchanges: no branches; the GPU's
/// traversal orders a node's children with it).
URBIS_HD inline void sortFour(uint32_t (&k)[4]) {
    auto exchange = [&](int a, int b) {
        const uint32_t lo = k[a] < k[b] ? k[a] : k[b], hi = k[a] < k[b] ? k[b] : k[a];
        k[a] = lo;
        k[b] = hi;
    };
    exchange(0, 1);
    exchange(2, 3);
    exchange(0, 2);
    exchange(1, 3);
    exchange(1, 2);
}

/// Closest-hit or any-hit (`anyHit`) traversal of a BVH built by buildBvh, in world space.
/// intersect(uint32_t prim, Ray& ray, HitRecord& hit) -> bool tests one primitive (prim indexes leaf
/// order, i.e. positions in the build's primOrder); on a hit it fills hit and shrinks ray.tmax.
/// Leaves of a visited node are tested at once (shrinking ray.tmax early); interior children are
/// visited nearest first and skipped when they start beyond the closest hit so far; any-hit
/// queries return at the first hit. Returns whether anything was hit. No allocation; fixed-size
/// stack. `anyHit` is a run-time flag so that one inlined copy can serve both queries where code
/// size matters (the GPU path tracer: see traceScene).
///
/// With CostlyLeaves, leaves marked kBvhCostlyLeaf go to intersectCostly instead. With Defer (by
/// default on the GPU only, where it pays) they are deferred: a lane holds one such leaf and goes on
/// with the traversal (or, with nothing else to do, waits) until every lane of its warp that is
/// traversing holds one (warpAll), so that the costly test runs with all of them; without, they
/// are tested where the traversal meets them. The order of tests then differs, so equal distances
/// go to the lower primitive index: the CPU and the GPU find the same hit. The CPU's tests run the
/// deferred traversal too, each ray its own warp. HitRecord is the callers' (Hit, or geometry/'s
/// PrimHit); the traversal only passes it on.
template <bool CostlyLeaves, bool Defer = CostlyLeaves && URBIS_GPU_CODE, typename HitRecord, typename IntersectPrim,
          typename IntersectCostly>
URBIS_HD bool traverseBvh(const BvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                          IntersectPrim&& intersect, IntersectCostly&& intersectCostly) {
    // A deferred leaf (one primitive: see buildBvh) on the stack or pending: its slot, with kLeafItem set.
    constexpr uint32_t kNoItem = 0xffffffffu, kLeafItem = 0x80000000u;
    constexpr uint32_t kLaneBits = kBvhWidth - 1;
    static_assert(CostlyLeaves || !Defer, "only costly leaves are deferred");
    constexpr bool kDefer = Defer;
    struct Entry {
        uint32_t item;
        float tEntry;
    };
    Entry stack[kBvhStackSize];
    int top = 0;
    bool found = false;
    uint32_t hitSlot = kNoItem, current = 0, pending = kNoItem;
    float pendingEntry = 0.0f;   // where the ray enters the pending leaf's box
    auto test = [&](auto& intersectPrim, uint32_t slot) {
        if (!CostlyLeaves) return intersectPrim(slot, ray, hit);
        const float tmax = ray.tmax;
        // A tie goes to the lower slot: it may test up to the next float (tmax is positive and finite).
        if (found && slot < hitSlot) ray.tmax = __builtin_bit_cast(float, __builtin_bit_cast(uint32_t, tmax) + 1u);
        if (intersectPrim(slot, ray, hit)) {
            hitSlot = slot;
            return true;
        }
        ray.tmax = tmax;
        return false;
    };
    // Pops the next subtree that may still hold something closer than ray.tmax into `current`, or the
    // next deferred leaf into `pending` if it is free. Returns whether `current` was set.
    auto popNext = [&] {
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.tEntry > ray.tmax) continue;
            if (kDefer && (e.item & kLeafItem)) {
                if (pending != kNoItem) {
                    ++top;   // one deferred leaf at a time
                    return false;
                }
                pending = e.item;
                pendingEntry = e.tEntry;
                continue;
            }
            current = e.item;
            return true;
        }
        return false;
    };
    for (;;) {
        if constexpr (kDefer) {
            if (warpAll(pending != kNoItem)) {
                // A hit found since the leaf was deferred may have put it out of reach.
                if (pendingEntry <= ray.tmax && test(intersectCostly, pending & ~kLeafItem)) {
                    found = true;
                    if (anyHit) return true;
                }
                pending = kNoItem;
            }
        }
        if (kDefer && current == kNoItem && !popNext()) {
            if (pending == kNoItem) return found;
            continue;   // nothing to do but the deferred leaf: wait for the warp
        }
        const BvhNode& node = nodes[current];
        float tEntry[kBvhWidth];
        const unsigned hitMask = intersectLanes(node, r, ray.tmin, ray.tmax, tEntry);
        // The node's children and leaf sizes, read at once and picked by selects: a loop that is not
        // unrolled would read them from memory lane by lane, each load's latency on the way.
        static_assert(kBvhWidth == 4, "at, sortFour and the lists below take four lanes");
        const uint32_t child[kBvhWidth] = {node.child[0], node.child[1], node.child[2], node.child[3]};
        const uint32_t count[kBvhWidth] = {node.primCount[0], node.primCount[1], node.primCount[2], node.primCount[3]};
        auto at = [](const uint32_t(&value)[kBvhWidth], uint32_t lane) {
            return lane & 2u ? (lane & 1u ? value[3] : value[2]) : (lane & 1u ? value[1] : value[0]);
        };
        unsigned leaves = 0, costly = 0;
        for (int l = 0; l < kBvhWidth; ++l) {
            leaves |= (count[l] != 0 ? 1u : 0u) << l;
            costly |= (count[l] & kBvhCostlyLeaf ? 1u : 0u) << l;
        }
        leaves &= hitMask;
        costly = kDefer ? costly & leaves : 0u;
        leaves &= ~costly;
#if URBIS_GPU_CODE
#pragma unroll(CostlyLeaves ? 1 : kBvhWidth)   // one copy of the primitive test beside the deferred one
#endif
        for (int l = 0; l < kBvhWidth; ++l) {
            if (!(leaves >> l & 1u)) continue;
            const uint32_t first = at(child, uint32_t(l)), size = at(count, uint32_t(l));
            const bool costlyNow = !kDefer && CostlyLeaves && (size & kBvhCostlyLeaf);
            for (uint32_t i = 0; i < (size & ~kBvhCostlyLeaf); ++i) {
                if (costlyNow ? test(intersectCostly, first + i) : test(intersect, first + i)) {
                    found = true;
                    if (anyHit) return true;
                }
            }
        }
        // Interior children (and deferred leaves) still in reach, visited nearest first: the nearest
        // interior child next if nothing deferred is nearer, the others pushed farthest first. The
        // nearest deferred leaf is held at once if no other is.
        unsigned inner = 0;
        for (int l = 0; l < kBvhWidth; ++l) {
            const bool inReach = hitMask >> l & 1u && tEntry[l] <= ray.tmax;
            inner |= (inReach && count[l] == 0 ? 1u : 0u) << l;
            costly &= ~((inReach ? 0u : 1u) << l);
        }
        if (kDefer && costly != 0 && pending == kNoItem) {
            int nearest = -1;
            for (int l = 0; l < kBvhWidth; ++l)
                if (costly >> l & 1u && (nearest < 0 || tEntry[l] < tEntry[nearest])) nearest = l;
            pending = kLeafItem | at(child, uint32_t(nearest));
            pendingEntry = tEntry[nearest];
            costly &= ~(1u << nearest);
        }
        // Ordered by keys of (entry distance, lane): a non-negative float's bits order as the float,
        // the lane takes the two lowest (and the stored distance loses them: it only culls, so a few
        // ulps less is safe).
        const unsigned queued = inner | costly;
        uint32_t key[kBvhWidth];
        for (int l = 0; l < kBvhWidth; ++l)
            key[l] = queued >> l & 1u ? (__builtin_bit_cast(uint32_t, tEntry[l]) & ~kLaneBits) | uint32_t(l) : ~0u;
        current = kNoItem;
#if URBIS_GPU_CODE
        // A sorting network, then the keys pushed in order; a lane's child by selects (`at`). 3-7 %
        // faster on the H200 than ranks (docs/gpu_notes.md § Traversal step).
        sortFour(key);
        for (int i = kBvhWidth - 1; i >= 0; --i) {
            if (key[i] == ~0u) continue;
            const uint32_t lane = key[i] & kLaneBits;
            const bool interior = inner >> lane & 1u;
            if (i == 0 && interior) current = at(child, lane);
            else stack[top++] = {at(child, lane) | (interior ? 0u : kLeafItem), __builtin_bit_cast(float, key[i] & ~kLaneBits)};
        }
#else
        // Each lane's place is its rank among the keys, written straight to the stack: the same
        // entries in the same places as the GPU's network, 7 % faster on the CPU (one thread).
        int queuedCount = 0;
        for (int l = 0; l < kBvhWidth; ++l) queuedCount += int(queued >> l & 1u);
        for (int l = 0; l < kBvhWidth; ++l) {
            if (!(queued >> l & 1u)) continue;
            int rank = 0;
            for (int m = 0; m < kBvhWidth; ++m) rank += int(key[m] < key[l]);
            const bool interior = inner >> l & 1u;
            if (rank == 0 && interior) current = child[l];
            else stack[top + queuedCount - 1 - rank] = {child[l] | (interior ? 0u : kLeafItem),
                                                  __builtin_bit_cast(float, key[l] & ~kLaneBits)};
        }
        top += queuedCount - (current != kNoItem ? 1 : 0);
#endif
        if (!kDefer && current == kNoItem && !popNext()) return found;
    }
}

/// traverseBvh without costly leaves: every primitive goes to `intersect`.
template <typename HitRecord, typename IntersectPrim>
URBIS_HD bool traverseBvh(const BvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                          IntersectPrim&& intersect) {
    return traverseBvh<false>(nodes, r, ray, hit, anyHit, intersect, intersect);
}

} // namespace urbis
