// Stack-based traversal of the 8-wide compressed BVH (host+device): eight lanes decoded and
// slab-tested at once, in scalar or SSE code here, AVX2 in wide_lanes_avx2.h, with the same results
// bit for bit.
#pragma once

#include "accel/bvh_traverse.h"
#include "accel/wide_bvh_node.h"
#include "math/ray.h"

#include <cstdint>

namespace urbis {

/// The instruction sets a wide node's eight lanes are tested in (WideLanesScalar, WideLanesSse,
/// WideLanesAvx2): all three compute the same values bit for bit (the same IEEE operations in the
/// same order), so they find the same hits. The GPU takes the scalar one.
enum class WideIsa : uint8_t { Scalar, Sse, Avx2 };

/// Entries of the traversal stack: the tree is under 64 levels; a node the traversal goes on into
/// pushes at most kWideBvhWidth - 1 entries, one it leaves kWideBvhWidth.
inline constexpr int kWideStackSize = 64 * (kWideBvhWidth - 1) + kWideBvhWidth;

/// The exit distance's factor 1 + 2 gamma(3) of Ize's robust slab test (intersectLanes).
inline constexpr float kWideRobustScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

/// The fastest lane test this CPU runs: AVX2 where it has it, else SSE on x86, else scalar (host).
WideIsa hostWideIsa();

/// Robust slab test (Ize 2013, as intersectLanes) of the ray against the decoded boxes of a wide
/// node's eight lanes, one lane at a time: writes each lane's entry distance and returns the mask of
/// lanes whose box overlaps [tmin, tmax]. Unused lanes' boxes are empty (lo above hi) and never do.
struct WideLanesScalar {
    URBIS_HD static unsigned test(const WideBvhNode& node, const BvhRay& r, float tmin, float tmax,
                                  float (&tEntry)[kWideBvhWidth]) {
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

/// Closest-hit or any-hit (`anyHit`) traversal of a WideBvh (buildWideBvh), in world space, its lanes
/// tested by Lanes (WideLanesScalar, WideLanesSse, WideLanesAvx2), with the
/// contract of traverseBvh without deferral: intersect(uint32_t prim, Ray& ray, HitRecord& hit) ->
/// bool tests one primitive (a position in the build's primOrder), filling hit and shrinking
/// ray.tmax on a hit; with CostlyLeaves, leaves marked kWideCostlyLeaf go to intersectCostly and
/// equal distances go to the lower primitive index. The leaves of a visited node are tested at once
/// in lane order; interior children in reach are visited nearest first, ordered by (entry distance,
/// lane) keys as traverseBvh's. No allocation; fixed-size stack.
template <typename Lanes, bool CostlyLeaves, typename HitRecord, typename IntersectPrim, typename IntersectCostly>
URBIS_HD bool traverseWideBvh(const WideBvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                              IntersectPrim&& intersect, IntersectCostly&& intersectCostly) {
    constexpr uint32_t kNoNode = 0xffffffffu, kLaneBits = kWideBvhWidth - 1;
    struct Entry {
        uint32_t node;
        float tEntry;
    };
    Entry stack[kWideStackSize];
    int top = 0;
    bool found = false;
    uint32_t hitSlot = kNoNode, current = 0;
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
    for (;;) {
        const WideBvhNode& node = nodes[current];
        float tEntry[kWideBvhWidth];
        const unsigned hitMask = Lanes::test(node, r, ray.tmin, ray.tmax, tEntry);
        const unsigned innerMask = node.innerMask;
        // Leaves hit, in lane order; a leaf's primitives follow those of the leaves in lower lanes.
        for (unsigned leaves = hitMask & ~innerMask, slot = node.primBase, l = 0; leaves >> l != 0; ++l) {
            const uint32_t info = node.leafInfo[l], size = info & 15u;
            if (leaves >> l & 1u) {
                for (uint32_t i = 0; i < size; ++i) {
                    bool hitNow;
                    if constexpr (CostlyLeaves)
                        hitNow = info & kWideCostlyLeaf ? test(intersectCostly, slot + i) : test(intersect, slot + i);
                    else
                        hitNow = intersect(slot + i, ray, hit);
                    if (hitNow) {
                        found = true;
                        if (anyHit) return true;
                    }
                }
            }
            slot += size;
        }
        // Interior children still in reach (a leaf's hit may have put some beyond it), nearest next and
        // the others pushed farthest first, each placed by its rank among (entry distance, lane) keys
        // (see traverseBvh).
        unsigned inner = hitMask & innerMask;
        uint32_t key[kWideBvhWidth];
        for (unsigned rest = inner; rest != 0; rest &= rest - 1) {
            const int l = lowestBit(rest);
            if (tEntry[l] > ray.tmax) inner &= ~(1u << l);
            key[l] = (__builtin_bit_cast(uint32_t, tEntry[l]) & ~kLaneBits) | uint32_t(l);
        }
        current = kNoNode;
        const int queuedCount = int(bitCount8(inner));
        for (unsigned rest = inner; rest != 0; rest &= rest - 1) {
            const int l = lowestBit(rest);
            int rank = 0;
            for (unsigned others = inner & (inner - 1u) ? inner : 0u; others != 0; others &= others - 1)
                rank += int(key[lowestBit(others)] < key[l]);
            const uint32_t child = node.childBase + bitCount8(innerMask & ((1u << l) - 1u));
            if (rank == 0) current = child;
            else stack[top + queuedCount - 1 - rank] = {child, __builtin_bit_cast(float, key[l] & ~kLaneBits)};
        }
        top += queuedCount > 0 ? queuedCount - 1 : 0;
        while (current == kNoNode && top > 0) {
            const Entry e = stack[--top];
            if (e.tEntry <= ray.tmax) current = e.node;
        }
        if (current == kNoNode) return found;
    }
}

/// traverseWideBvh without costly leaves: every primitive goes to `intersect`.
template <typename Lanes, typename HitRecord, typename IntersectPrim>
URBIS_HD bool traverseWideBvh(const WideBvhNode* nodes, const BvhRay& r, Ray& ray, HitRecord& hit, bool anyHit,
                              IntersectPrim&& intersect) {
    return traverseWideBvh<Lanes, false>(nodes, r, ray, hit, anyHit, intersect, intersect);
}

} // namespace urbis
