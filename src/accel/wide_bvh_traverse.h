// Stack-based traversal of the 8-wide compressed BVH (host+device): eight lanes decoded and
// slab-tested at once, in scalar or SSE code here, AVX2 in wide_lanes_avx2.h, with the same results
// bit for bit.
#pragma once

#include "accel/bvh_traverse.h"   // BvhRay, warpAll
#include "accel/wide_bvh_node.h"
#include "accel/wide_isa.h"
#include "math/ray.h"

#include <cstddef>
#include <cstdint>

#if URBIS_HAVE_SSE
#include <emmintrin.h>
#endif

namespace urbis {

/// Entries of the traversal stack: the tree is under 64 levels; a node the traversal goes on into
/// pushes at most kWideBvhWidth - 1 entries, one it leaves kWideBvhWidth.
inline constexpr int kWideStackSize = 64 * (kWideBvhWidth - 1) + kWideBvhWidth;

/// The exit distance's factor 1 + 2 gamma(3) of the robust slab test ("Robust BVH Ray Traversal",
/// T. Ize, JCGT 2(2), 2013): rounding never culls a box the ray touches.
inline constexpr float kWideRobustScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

/// Robust slab test (Ize 2013, kWideRobustScale) of the ray against the decoded boxes of a wide
/// node's eight lanes, one lane at a time: writes each lane's entry distance and returns the mask of
/// lanes whose box overlaps [tmin, tmax]. Unused lanes' boxes are empty (lo above hi) and never do.
struct WideLanesScalar {
    URBIS_HD static unsigned test(const WideBvhNode& node, const BvhRay& r, float tmin, float tmax,
                                  float (&tEntry)[kWideBvhWidth]) {
#if URBIS_GPU_CODE
        // The 48 plane bytes in three 16-byte loads, not 48 byte loads, and each row picked by selects:
        // an array indexed by the ray's near planes would live in local memory. A byte becomes its float
        // exactly as a float's mantissa (2^23 + q - 2^23): full-rate operations, where int-to-float
        // conversions run at a quarter rate.
        static_assert(offsetof(WideBvhNode, q) % 16 == 0, "the planes load as 16-byte words");
        const uint4* rows = reinterpret_cast<const uint4*>(node.q);
        const uint4 a = rows[0], b = rows[1], c = rows[2];
        const uint32_t word[12] = {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w, c.x, c.y, c.z, c.w};
        uint32_t nearWord[3][2], farWord[3][2];
#pragma unroll
        for (int axis = 0; axis < 3; ++axis) {
            const bool flipped = r.nearPlane[axis] != axis;
#pragma unroll
            for (int half = 0; half < 2; ++half) {
                const uint32_t lo = word[2 * axis + half], hi = word[2 * axis + 6 + half];
                nearWord[axis][half] = flipped ? hi : lo;
                farWord[axis][half] = flipped ? lo : hi;
            }
        }
        // Plane `value` of `axis` as a distance along the ray.
        auto distance = [&](int axis, uint32_t value) {
            const float q = __fsub_rn(__uint_as_float(0x4b000000u | value), 8388608.0f);
            const float plane = exactAdd(node.origin[axis], exactMul(q, node.step(axis)));
            return exactMul(exactSub(plane, r.origin[axis]), r.invDir[axis]);
        };
        // The lanes in a loop, not unrolled: the render kernel with walls is bound by fetching
        // instructions, and took 1.5x the time with the lanes unrolled (docs/accel_notes.md).
        unsigned mask = 0;
        URBIS_NO_UNROLL
        for (int l = 0; l < kWideBvhWidth; ++l) {
            const uint32_t shift = 8 * (l & 3), half = l >> 2;
            const float nx = distance(0, nearWord[0][half] >> shift & 0xffu);
            const float ny = distance(1, nearWord[1][half] >> shift & 0xffu);
            const float nz = distance(2, nearWord[2][half] >> shift & 0xffu);
            const float fx = exactMul(distance(0, farWord[0][half] >> shift & 0xffu), kWideRobustScale);
            const float fy = exactMul(distance(1, farWord[1][half] >> shift & 0xffu), kWideRobustScale);
            const float fz = exactMul(distance(2, farWord[2][half] >> shift & 0xffu), kWideRobustScale);
#else
        const uint8_t* nearX = node.q[r.nearPlane[0]];
        const uint8_t* nearY = node.q[r.nearPlane[1]];
        const uint8_t* nearZ = node.q[r.nearPlane[2]];
        const uint8_t* farX = node.q[(r.nearPlane[0] + 3) % 6];
        const uint8_t* farY = node.q[(r.nearPlane[1] + 3) % 6];
        const uint8_t* farZ = node.q[(r.nearPlane[2] + 3) % 6];
        unsigned mask = 0;
        for (int l = 0; l < kWideBvhWidth; ++l) {
            const float nx = (node.decodePlane(0, nearX[l]) - r.origin[0]) * r.invDir[0];
            const float ny = (node.decodePlane(1, nearY[l]) - r.origin[1]) * r.invDir[1];
            const float nz = (node.decodePlane(2, nearZ[l]) - r.origin[2]) * r.invDir[2];
            const float fx = (node.decodePlane(0, farX[l]) - r.origin[0]) * r.invDir[0] * kWideRobustScale;
            const float fy = (node.decodePlane(1, farY[l]) - r.origin[1]) * r.invDir[1] * kWideRobustScale;
            const float fz = (node.decodePlane(2, farZ[l]) - r.origin[2]) * r.invDir[2] * kWideRobustScale;
#endif
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
    }
};

#if URBIS_HAVE_SSE
/// WideLanesScalar's test in SSE2: the eight lanes as two halves of four.
struct WideLanesSse {
    static unsigned test(const WideBvhNode& node, const BvhRay& r, float tmin, float tmax, float (&tEntry)[kWideBvhWidth]) {
        const __m128i zero = _mm_setzero_si128();
        // Lanes [4 half, 4 half + 4) of plane row `row`, decoded along `axis`: bytes widened to floats.
        auto decode = [&](int row, int axis, int half) {
            const __m128i bytes = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(node.q[row]));
            const __m128i words = _mm_unpacklo_epi8(bytes, zero);
            const __m128i ints = half == 0 ? _mm_unpacklo_epi16(words, zero) : _mm_unpackhi_epi16(words, zero);
            return _mm_add_ps(_mm_set1_ps(node.origin[axis]), _mm_mul_ps(_mm_cvtepi32_ps(ints), _mm_set1_ps(node.step(axis))));
        };
        const __m128 scale = _mm_set1_ps(kWideRobustScale);
        unsigned mask = 0;
        for (int half = 0; half < 2; ++half) {
            __m128 t0 = _mm_set1_ps(tmin), t1 = _mm_set1_ps(tmax);
            for (int axis = 0; axis < 3; ++axis) {
                const __m128 o = _mm_set1_ps(r.origin[axis]), inv = _mm_set1_ps(r.invDir[axis]);
                const __m128 n = _mm_mul_ps(_mm_sub_ps(decode(r.nearPlane[axis], axis, half), o), inv);
                const __m128 f = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(decode((r.nearPlane[axis] + 3) % 6, axis, half), o), inv), scale);
                // _mm_max_ps(a, b) is a > b ? a : b, as in the scalar path.
                t0 = _mm_max_ps(n, t0);
                t1 = _mm_min_ps(f, t1);
            }
            _mm_storeu_ps(tEntry + 4 * half, t0);
            mask |= unsigned(_mm_movemask_ps(_mm_cmple_ps(t0, t1))) << (4 * half);
        }
        return mask;
    }
};
#endif

/// The index of the lowest set bit of `bits` (not zero).
URBIS_HD inline int lowestBit(uint32_t bits) {
#if URBIS_GPU_CODE
    return __ffs(bits) - 1;
#else
    return __builtin_ctz(bits);
#endif
}

/// Set bits of an 8-bit mask, in a few shifts and adds: baseline x86-64 has no popcnt instruction,
/// and g++'s __builtin_popcount there is a library call.
URBIS_HD inline uint32_t bitCount8(uint32_t bits) {
    bits = bits - ((bits >> 1) & 0x55u);
    bits = (bits & 0x33u) + ((bits >> 2) & 0x33u);
    return (bits + (bits >> 4)) & 0x0fu;
}

/// The position, in the build's primOrder, of the first primitive of leaf lane `lane`: the node's
/// primBase plus the sizes of the leaf lanes below it (four bits a lane, summed as bytes at once).
URBIS_HD inline uint32_t wideLeafFirst(const WideBvhNode& node, int lane) {
    static_assert(kWideBvhWidth == 8 && offsetof(WideBvhNode, leafInfo) % 8 == 0, "the leaf sizes load as one word");
    uint64_t info;
    __builtin_memcpy(&info, node.leafInfo, sizeof info);
    const uint64_t sizes = info & 0x0f0f0f0f0f0f0f0full;
    const uint64_t below = lane == 0 ? 0u : sizes & (~uint64_t(0) >> (64 - 8 * lane));
    return node.primBase + uint32_t((below * 0x0101010101010101ull) >> 56);
}

/// Closest-hit or any-hit (`anyHit`) traversal of a WideBvh (buildWideBvh), in world space, its lanes
/// tested by Lanes (WideLanesScalar, WideLanesSse, WideLanesAvx2), with the contract of traverseBvh:
/// intersect(uint32_t prim, Ray& ray, HitRecord& hit) -> bool tests one primitive (a position in the
/// build's primOrder), filling hit and shrinking ray.tmax on a hit. The leaves of a visited node are
/// tested at once in lane order; interior children in reach are visited nearest first, ordered by
/// (entry distance, lane) keys. No allocation; fixed-size stack.
///
/// With CostlyLeaves, leaves marked kWideCostlyLeaf (one primitive each) go to intersectCostly, ordered
/// among the interior children by where the ray enters them, and equal distances go to the lower
/// primitive index, so that the order of tests does not change the hit. A costly leaf's turn comes when
/// it is the nearest item left: without Defer it is tested then; with Defer (by default on the GPU only,
/// where it pays) the ray holds it and goes on with the traversal (or, with nothing else to do, waits)
/// until every lane of its warp that is traversing holds one (warpAll), so that the costly test runs
/// with all of them. Both find the same hit; the CPU's tests run the deferred traversal too.
template <typename Lanes, bool CostlyLeaves, bool Defer = CostlyLeaves && URBIS_GPU_CODE, typename HitRecord,
          typename IntersectPrim, typename IntersectCostly>
URBIS_HD bool traverseWideBvh(const WideBvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                              IntersectPrim&& intersect, IntersectCostly&& intersectCostly) {
    // A deferred leaf on the stack or pending: its primitive's position, with kLeafItem set.
    constexpr uint32_t kNoItem = 0xffffffffu, kLeafItem = 0x80000000u, kLaneBits = kWideBvhWidth - 1;
    static_assert(CostlyLeaves || !Defer, "only costly leaves are deferred");
    struct Entry {
        uint32_t item;
        float tEntry;
    };
    Entry stack[kWideStackSize];
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
    // Pops the next item that may still hold something closer than ray.tmax: a subtree into `current`
    // (then returns true), a costly leaf into `pending` with Defer if it is free (one at a time), or
    // without Defer through its test (an any-hit query then empties the stack).
    auto popNext = [&] {
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.tEntry > ray.tmax) continue;
            if (e.item & kLeafItem) {
                if (Defer) {
                    if (pending != kNoItem) {
                        ++top;
                        return false;
                    }
                    pending = e.item;
                    pendingEntry = e.tEntry;
                } else if (test(intersectCostly, e.item & ~kLeafItem)) {
                    found = true;
                    if (anyHit) top = 0;
                }
                continue;
            }
            current = e.item;
            return true;
        }
        return false;
    };
    for (;;) {
        if constexpr (Defer) {
            if (warpAll(pending != kNoItem)) {
                // A hit found since the leaf was deferred may have put it out of reach.
                if (pendingEntry <= ray.tmax && test(intersectCostly, pending & ~kLeafItem)) {
                    found = true;
                    if (anyHit) return true;
                }
                pending = kNoItem;
            }
            if (current == kNoItem && !popNext()) {
                if (pending == kNoItem) return found;
                continue;   // nothing to do but the deferred leaf: wait for the warp
            }
        }
        const WideBvhNode& node = nodes[current];
        float tEntry[kWideBvhWidth];
        const unsigned hitMask = Lanes::test(node, r, ray.tmin, ray.tmax, tEntry);
        const unsigned innerMask = node.innerMask;
        // Cheap leaves hit, in lane order: a leaf's primitives follow those of the leaves in lower lanes.
        // The lane's info is read from the node, never from an array indexed by lane: on the GPU such an
        // array would live in local memory. Costly leaves wait their turn among the interior children.
        unsigned costly = 0;
        URBIS_NO_UNROLL
        for (unsigned leaves = hitMask & ~innerMask; leaves != 0; leaves &= leaves - 1) {
            const int l = lowestBit(leaves);
            const uint32_t info = node.leafInfo[l], size = info & 15u;
            if (CostlyLeaves && (info & kWideCostlyLeaf)) {
                costly |= 1u << l;
                continue;
            }
            for (uint32_t i = 0, first = wideLeafFirst(node, l); i < size; ++i) {
                if (test(intersect, first + i)) {
                    found = true;
                    if (anyHit) return true;
                }
            }
        }
        // Interior children and costly leaves still in reach, nearest first: the nearest interior child
        // next if no costly leaf is nearer, the others pushed farthest first, each placed by its rank
        // among (entry distance, lane) keys: a non-negative float's bits order as the float, the lane
        // takes the three lowest (and the stored distance loses them: it only culls, so a few ulps less
        // is safe). A costly leaf is tested (with Defer: held) when it is the nearest item left, so
        // that nearer subtrees may hit first and put it out of reach. The GPU runs these loops as they
        // are: with every lane at a constant index (keys in registers) the render kernel with walls,
        // bound by fetching instructions, took 1.5x the time.
        unsigned inner = hitMask & innerMask;
        uint32_t key[kWideBvhWidth];
        for (unsigned rest = inner | costly; rest != 0; rest &= rest - 1) {
            const int l = lowestBit(rest);
            if (tEntry[l] > ray.tmax) {
                inner &= ~(1u << l);
                costly &= ~(1u << l);
            }
            key[l] = (__builtin_bit_cast(uint32_t, tEntry[l]) & ~kLaneBits) | uint32_t(l);
        }
        const unsigned queued = inner | costly;
        const int queuedCount = int(bitCount8(queued));
        current = kNoItem;
        for (unsigned rest = queued; rest != 0; rest &= rest - 1) {
            const int l = lowestBit(rest);
            int rank = 0;
            for (unsigned others = queued & (queued - 1u) ? queued : 0u; others != 0; others &= others - 1)
                rank += int(key[lowestBit(others)] < key[l]);
            const bool interior = inner >> l & 1u;
            const uint32_t item = interior ? node.childBase + bitCount8(innerMask & ((1u << l) - 1u))
                                           : kLeafItem | wideLeafFirst(node, l);
            if (rank == 0 && interior) current = item;
            else stack[top + queuedCount - 1 - rank] = {item, __builtin_bit_cast(float, key[l] & ~kLaneBits)};
        }
        top += queuedCount - (current != kNoItem ? 1 : 0);
        if (!Defer && current == kNoItem && !popNext()) return found;
    }
}

/// traverseWideBvh without costly leaves: every primitive goes to `intersect`.
template <typename Lanes, typename HitRecord, typename IntersectPrim>
URBIS_HD bool traverseWideBvh(const WideBvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                              IntersectPrim&& intersect) {
    return traverseWideBvh<Lanes, false>(nodes, r, ray, hit, anyHit, intersect, intersect);
}

} // namespace urbis
