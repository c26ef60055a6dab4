// Ray/tree intersection (host+device): sphere tracing of the tree's distance bound
// (scene/tree_shape.h) inside its box. Steps of f / lipschitz never pass the surface, so a tree is
// never missed between two steps (Hart, "Sphere tracing", The Visual Computer 12, 1996); a hit is
// declared where f falls under kTreeHitDistance. Everything that decides a hit uses urbis.h's exact
// operations (as the distance function does), so both backends take the same steps bit for bit.
#pragma once

#include "math/ray.h"
#include "scene/tree_shape.h"

namespace urbis {

/// f (metres, before division by the Lipschitz bound) under which a step counts as a hit: the
/// surface lies within this of the hit point (tests/tree_intersect_test.cpp measures it).
inline constexpr float kTreeHitDistance = 2e-3f;
/// Steps before the trace gives up. A ray that is still inside the box then is taken as a hit where
/// f is under ten times kTreeHitDistance (a grazing ray creeping along the crown) and a miss otherwise.
inline constexpr int kTreeMaxSteps = 160;

/// Whether `ray` meets `tree` with ray.tmin < t < ray.tmax: then t (units of |ray.dir|) and the
/// steps it took. `invDir`: BvhRay's safeInverse of ray.dir. A ray that starts on the tree's surface
/// (f under twice kTreeHitDistance: a bounce or shadow ray leaving it) must come closer than half its
/// start's f before it hits, so it does not hit the surface it leaves.
URBIS_HD inline bool intersectTree(const TreeRecord& tree, const TreeShapeParams& s, const Ray& ray, const float invDir[3],
                                   float& tHit, int* steps = nullptr) {
    const Vec3f o = exactSub3(ray.origin, tree.base);
    const Bounds3f box = treeLocalBounds(s);
    float t0 = ray.tmin, t1 = ray.tmax;
    for (int axis = 0; axis < 3; ++axis) {
        float a = exactMul(exactSub(box.lo[axis], o[axis]), invDir[axis]);
        float b = exactMul(exactSub(box.hi[axis], o[axis]), invDir[axis]);
        if (a > b) {
            const float c = a;
            a = b;
            b = c;
        }
        t0 = fmaxf(t0, a);
        t1 = fminf(t1, b);
    }
    if (!(t0 <= t1)) return false;
    // t advances by f / (lipschitz |dir|): distances are metres, t is in units of |dir|.
    const float stepScale = exactDiv(1.0f, exactMul(s.lipschitz, exactLength(ray.dir)));
    float t = t0, threshold = kTreeHitDistance;
    URBIS_NO_UNROLL
    for (int i = 0; i < kTreeMaxSteps; ++i) {
        const Vec3f q{exactMulAdd(t, ray.dir.x, o.x), exactMulAdd(t, ray.dir.y, o.y), exactMulAdd(t, ray.dir.z, o.z)};
        const float f = treeDistance(s, q);
        if (i == 0 && f < 2.0f * kTreeHitDistance) threshold = 0.5f * f;
        if (f < threshold || (i == kTreeMaxSteps - 1 && f < 10.0f * kTreeHitDistance)) {
            if (steps) *steps = i + 1;
            if (!(t > ray.tmin)) return false;
            tHit = t;
            return true;
        }
        t = exactMulAdd(f, stepScale, t);
        if (t > t1) break;
    }
    if (steps) *steps = kTreeMaxSteps;
    return false;
}

} // namespace urbis
