// Stack-based traversal of a flat binary BVH (host+device).
#pragma once

#include "accel/bvh_node.h"
#include "math/ray.h"

#include <cfloat>
#include <cstdint>

namespace urbis {

/// Entries of the traversal stack; the builder keeps depth below this.
inline constexpr int kBvhStackSize = 64;

/// What the slab test needs of a ray, computed once per ray.
struct BvhRay {
    float origin[3];
    float invDir[3];
    int nearOffset[3];   ///< 0 if the direction is positive along the axis (near plane = lo), else 3

    /// 1/x, or ±FLT_MAX where |x| is so small that 1/x would overflow; keeps (plane - origin)
    /// * invDir free of NaN (0 * inf) for axis-parallel rays.
    URBIS_HD static float safeInverse(float x) {
        const float tiny = 1.0f / FLT_MAX;
        if (x >= 0.0f && x <= tiny) return FLT_MAX;
        if (x < 0.0f && x >= -tiny) return -FLT_MAX;
        return 1.0f / x;
    }

    URBIS_HD explicit BvhRay(const Ray& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = ray.origin[axis];
            invDir[axis] = safeInverse(ray.dir[axis]);
            nearOffset[axis] = invDir[axis] < 0.0f ? 3 : 0;
        }
    }
};

/// Robust ray/box slab test: the exit distance is scaled by 1 + 2 gamma(3) so that rounding
/// never culls a box the ray touches. See "Robust BVH Ray Traversal", T. Ize, JCGT 2(2),
/// 2013. Returns whether [tmin, tmax] overlaps the box, with the entry distance in tEntry.
URBIS_HD inline bool intersectNode(const BvhNode& node, const BvhRay& r, float tmin, float tmax, float& tEntry) {
    constexpr float kRobustScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
    float t0 = tmin, t1 = tmax;
    for (int axis = 0; axis < 3; ++axis) {
        const float tNear = (node.bounds[r.nearOffset[axis] + axis] - r.origin[axis]) * r.invDir[axis];
        const float tFar = (node.bounds[3 - r.nearOffset[axis] + axis] - r.origin[axis]) * r.invDir[axis];
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar * kRobustScale < t1 ? tFar * kRobustScale : t1;
    }
    tEntry = t0;
    return t0 <= t1;
}

/// Closest-hit (AnyHit = false) or any-hit (AnyHit = true) traversal of a binary BVH built
/// by buildBvh, in world space: near child first, subtrees beyond the current closest hit
/// skipped, early exit on the first hit for any-hit queries.
/// intersect(uint32_t prim, Ray& ray, Hit& hit) -> bool tests one primitive (prim indexes
/// leaf order, i.e. the build's primOrder positions); on a hit it fills hit and shrinks
/// ray.tmax. Returns whether anything was hit. No allocation; fixed-size stack.
template <bool AnyHit, typename IntersectPrim>
URBIS_HD bool traverseBvh(const BvhNode* nodes, Ray& ray, Hit& hit, IntersectPrim&& intersect) {
    const BvhRay r(ray);
    struct Entry {
        uint32_t node;
        float tEntry;
    };
    Entry stack[kBvhStackSize];
    int top = 0;
    bool found = false;
    float tRoot;
    if (!intersectNode(nodes[0], r, ray.tmin, ray.tmax, tRoot)) return false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        if (node.isLeaf()) {
            for (uint32_t i = 0; i < node.primCount; ++i) {
                if (intersect(node.first + i, ray, hit)) {
                    found = true;
                    if constexpr (AnyHit) return true;
                }
            }
        } else {
            float tLeft, tRight;
            const uint32_t left = node.first;
            const bool hitLeft = intersectNode(nodes[left], r, ray.tmin, ray.tmax, tLeft);
            const bool hitRight = intersectNode(nodes[left + 1], r, ray.tmin, ray.tmax, tRight);
            if (hitLeft && hitRight) {
                const bool leftFirst = tLeft <= tRight;
                stack[top++] = leftFirst ? Entry{left + 1, tRight} : Entry{left, tLeft};
                current = leftFirst ? left : left + 1;
                continue;
            }
            if (hitLeft || hitRight) {
                current = hitLeft ? left : left + 1;
                continue;
            }
        }
        // Pop the next subtree that may still hold something closer than ray.tmax.
        for (;;) {
            if (top == 0) return found;
            const Entry e = stack[--top];
            if (e.tEntry <= ray.tmax) {
                current = e.node;
                break;
            }
        }
    }
}

} // namespace urbis
