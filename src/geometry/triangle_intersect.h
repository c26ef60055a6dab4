// Watertight ray/triangle intersection (host+device).
#pragma once

#include "accel/bvh_traverse.h"
#include "math/ray.h"
#include "scene/triangle.h"

namespace urbis {

/// The per-ray part of the watertight test, computed once per ray and reused for every
/// triangle: the axis permutation (kz is the dominant axis of the direction) and the shear
/// that maps the ray onto the +z axis. See "Watertight Ray/Triangle Intersection",
/// S. Woop, C. Benthin, I. Wald, JCGT 2(1), 2013, section 3.
struct WatertightRay {
    Vec3f origin;      ///< world space, metres
    int kx = 0, ky = 1, kz = 2;
    float sx = 0, sy = 0, sz = 1;

    WatertightRay() = default;
    /// `invDir`: BvhRay's 1 / ray.dir per axis (1 / ray.dir[kz] among them), which the traversal works
    /// out anyway.
    URBIS_HD WatertightRay(const Ray& ray, const float (&invDir)[3]) : origin(ray.origin) {
        kz = maxAbsAxis(ray.dir);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        // Swapping kx and ky keeps the winding, so the sign of the determinant keeps meaning.
        if (ray.dir[kz] < 0.0f) {
            int swap = kx;
            kx = ky;
            ky = swap;
        }
        sx = exactDiv(ray.dir[kx], ray.dir[kz]);
        sy = exactDiv(ray.dir[ky], ray.dir[kz]);
        sz = kz == 0 ? invDir[0] : (kz == 1 ? invDir[1] : invDir[2]);
    }
    URBIS_HD explicit WatertightRay(const Ray& ray) : WatertightRay(ray, BvhRay(ray).invDir) {}
};

/// a*b - c*d rounded as two products and one difference, never contracted to a fused
/// multiply-add: edge functions of a shared edge must be exact negatives of each other in
/// both triangles, or rays leak between them (the GPU build contracts; g++ does not in ISO mode).
URBIS_HD inline float differenceOfProductsUnfused(float a, float b, float c, float d) {
    return exactSub(exactMul(a, b), exactMul(c, d));
}

/// The edge functions e0, e1, e2 of the sheared vertices again in double, where the products and the
/// difference are exact, rounded once to float: for a ray through an edge or a vertex, where one of
/// them is zero in float (Woop, Benthin, Wald 2013, section 3.3).
URBIS_HD inline void edgeFunctionsInDouble(float ax, float ay, float bx, float by, float cx, float cy, float& e0,
                                           float& e1, float& e2) {
    e0 = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
    e1 = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
    e2 = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
}

/// Watertight intersection of a ray with a two-sided triangle (Woop, Benthin, Wald 2013):
/// rays through a shared edge or vertex of a closed mesh always hit one of its triangles.
/// On a hit with ray.tmin < t < ray.tmax (strictly) returns true and sets t (in units of
/// |ray.dir|) and the barycentrics u, v of p1 and p2: hit point = (1-u-v) p0 + u p1 + v p2.
/// Degenerate (zero-area or edge-on) triangles never hit.
URBIS_HD inline bool intersectTriangle(const Triangle& tri, const Ray& ray, const WatertightRay& wr,
                                       float& t, float& u, float& v) {
    // Vertices relative to the origin, as arrays: indexing by kx, ky, kz is then a load, not
    // a chain of selects.
    const float a[3] = {tri.p0.x - wr.origin.x, tri.p0.y - wr.origin.y, tri.p0.z - wr.origin.z};
    const float b[3] = {tri.p1.x - wr.origin.x, tri.p1.y - wr.origin.y, tri.p1.z - wr.origin.z};
    const float c[3] = {tri.p2.x - wr.origin.x, tri.p2.y - wr.origin.y, tri.p2.z - wr.origin.z};
    // Shear and scale the vertices into ray space, where the ray is the +z axis.
    const float az = a[wr.kz], bz = b[wr.kz], cz = c[wr.kz];
    // Every product that meets a sum is exact (urbis.h): the test decides hits on both backends.
    const float ax = a[wr.kx] - exactMul(wr.sx, az), ay = a[wr.ky] - exactMul(wr.sy, az);
    const float bx = b[wr.kx] - exactMul(wr.sx, bz), by = b[wr.ky] - exactMul(wr.sy, bz);
    const float cx = c[wr.kx] - exactMul(wr.sx, cz), cy = c[wr.ky] - exactMul(wr.sy, cz);
    // Scaled barycentrics: 2D edge functions of the projected edges bc, ca, ab.
    float e0 = differenceOfProductsUnfused(cx, by, cy, bx);
    float e1 = differenceOfProductsUnfused(ax, cy, ay, cx);
    float e2 = differenceOfProductsUnfused(bx, ay, by, ax);
    // Exactly on an edge in float: decide in double, which is exact here (section 3.3).
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) edgeFunctionsInDouble(ax, ay, bx, by, cx, cy, e0, e1, e2);
    // Both faces: the edge functions must not have mixed signs.
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
    const float det = e0 + e1 + e2;
    if (det == 0.0f) return false;
    const float scaledT = exactMul(e0, wr.sz * az) + exactMul(e1, wr.sz * bz) + exactMul(e2, wr.sz * cz);
    const float invDet = exactDiv(1.0f, det);
    const float hitT = scaledT * invDet;
    if (!(hitT > ray.tmin && hitT < ray.tmax)) return false;
    t = hitT;
    u = e1 * invDet;
    v = e2 * invDet;
    return true;
}

/// Convenience overload that builds the per-ray shear itself; prefer the one above when
/// testing a ray against many triangles.
URBIS_HD inline bool intersectTriangle(const Triangle& tri, const Ray& ray, float& t, float& u, float& v) {
    return intersectTriangle(tri, ray, WatertightRay(ray), t, u, v);
}

} // namespace urbis
