// Ray/forest intersection (host+device): a 2D walk (DDA; Amanatides and Woo, "A fast voxel traversal
// algorithm", Eurographics 1987) over the cells of a ForestRecord that the ray's projection on the
// ground crosses. A tree's box reaches up to `neighbours` cells beyond its own, so the walk keeps a
// window of cells around the current one and tests each tree once, when it enters the window, over
// the whole ray (the sphere trace of geometry/tree_intersect.h). The hit is the nearest over every
// tree tested, and the walk stops at the first cell that starts beyond it: a hit point lies in some
// cell the walk reached before it, and its tree in that cell's window, so no tree is missed and the
// distance is the one a test of every tree would give.
#pragma once

#include "geometry/tree_intersect.h"
#include "scene/forest_cells.h"

namespace urbis {

/// Clips [t0, t1] to the ray's interval in the box [lo, hi] (exact slabs); false if empty.
URBIS_HD inline bool clipToBox(const Ray& ray, const float invDir[3], Vec3f lo, Vec3f hi, float& t0, float& t1) {
    for (int axis = 0; axis < 3; ++axis) {
        const float a = exactMul(exactSub(lo[axis], ray.origin[axis]), invDir[axis]);
        const float b = exactMul(exactSub(hi[axis], ray.origin[axis]), invDir[axis]);
        t0 = fmaxf(t0, fminf(a, b));
        t1 = fminf(t1, fmaxf(a, b));
    }
    return t0 <= t1;
}

/// Whether `ray` (`invDir`: BvhRay's safeInverse of its direction) meets a tree of `forest` with
/// ray.tmin < t < ray.tmax: then the nearest t (any, with `anyHit`) and its tree's cell (i, k).
URBIS_HD inline bool intersectForest(const ForestRecord& f, const ForestGround& ground, const Ray& ray, const float invDir[3],
                                     bool anyHit, float& tHit, int32_t cell[2]) {
    const Bounds3f box = primBounds(f);
    float t0 = ray.tmin, t1 = ray.tmax;
    if (!clipToBox(ray, invDir, box.lo, box.hi, t0, t1)) return false;
    Ray r = ray;
    bool found = false;
    // Tests cell (i, k)'s tree over the whole ray (first against the box any tree of the forest would
    // have there, which spares most the shape's set-up); true once the walk may stop (an any-hit found).
    const Vec3f reach{f.reach, 0.0f, f.reach}, up{f.reach, f.top, f.reach};
    const auto test = [&](int32_t i, int32_t k) {
        TreeRecord tree;
        float ta = r.tmin, tb = r.tmax, t;
        if (!forestTreeAt(f, ground, i, k, tree) || !clipToBox(r, invDir, tree.base - reach, tree.base + up, ta, tb) ||
            !intersectTree(tree, treeShapeOf(tree), r, invDir, t))
            return false;
        r.tmax = t;
        tHit = t;
        cell[0] = i, cell[1] = k;
        found = true;
        return anyHit;
    };
    const int32_t n = f.neighbours;
    const float invCell = exactDiv(1.0f, f.cell);
    int32_t ci = int32_t(floorf(exactMul(exactMulAdd(t0, ray.dir.x, ray.origin.x), invCell)));
    int32_t ck = int32_t(floorf(exactMul(exactMulAdd(t0, ray.dir.z, ray.origin.z), invCell)));
    for (int32_t di = -n; di <= n; ++di)
        for (int32_t dk = -n; dk <= n; ++dk)
            if (test(ci + di, ck + dk)) return true;
    // Where the ray crosses the next cell border along x and along z, from the border's index each
    // time (no sum that drifts); a direction along the other axis never crosses.
    const int32_t sx = ray.dir.x > 0.0f ? 1 : -1, sz = ray.dir.z > 0.0f ? 1 : -1;
    const auto crossing = [&](int32_t c, int32_t s, int axis) {
        if (ray.dir[axis] == 0.0f) return 3.0e38f;
        return exactMul(exactSub(exactMul(float(s > 0 ? c + 1 : c), f.cell), ray.origin[axis]), invDir[axis]);
    };
    float nextX = crossing(ci, sx, 0), nextZ = crossing(ck, sz, 2);
    URBIS_NO_UNROLL
    for (;;) {
        const bool alongX = nextX < nextZ;
        if (!((alongX ? nextX : nextZ) <= fminf(t1, r.tmax))) break;
        if (alongX) {
            ci += sx;
            nextX = crossing(ci, sx, 0);
            for (int32_t dk = -n; dk <= n; ++dk)
                if (test(ci + sx * n, ck + dk)) return true;
        } else {
            ck += sz;
            nextZ = crossing(ck, sz, 2);
            for (int32_t di = -n; di <= n; ++di)
                if (test(ci + di, ck + sz * n)) return true;
        }
    }
    return found;
}

} // namespace urbis
