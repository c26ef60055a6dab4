// Closest-hit and shadow queries against triangles stored in the 4-wide BVH's leaf order (host+device):
// the reference that the tests and urbis_bench compare traceWideTriangles
// (src/geometry/wide_triangle_scene.h) with.
#pragma once

#include "bvh4/traverse.h"
#include "geometry/triangle_intersect.h"
#include "scene/triangle.h"

#include <cstdint>

namespace urbis {

/// Non-owning view of a triangle BVH: nodes from buildBvh over the triangles' bounds and the
/// triangles reordered by its primOrder (triangles[i] = original[primOrder[i]]).
struct TriangleSceneView {
    const BvhNode* nodes;
    const Triangle* triangles;
    uint32_t triangleCount;
};

/// Tests triangles[prim] (watertight); on a hit fills h and shrinks r.tmax to its distance.
URBIS_HD inline bool hitTriangle(const Triangle* triangles, const WatertightRay& wr, uint32_t prim, Ray& r, Hit& h) {
    float t, u, v;
    if (!intersectTriangle(triangles[prim], r, wr, t, u, v)) return false;
    h = {prim, t, u, v};
    r.tmax = t;
    return true;
}

/// The closest triangle hit with ray.tmin < t < ray.tmax (anyHit false), or the first one found
/// in any order (anyHit true: a shadow ray), in world space. Hit::prim is the index into
/// view.triangles (leaf order); invalid if nothing is hit. Watertight (Woop et al. 2013) and
/// robust in the BVH (Ize 2013).
URBIS_HD inline Hit traceTriangles(const TriangleSceneView& view, Ray ray, bool anyHit) {
    const BvhRay br(ray);
    const WatertightRay wr(ray, br.invDir);
    Hit hit;
    traverseBvh(view.nodes, br, ray, hit, anyHit,
                [&](uint32_t prim, Ray& r, Hit& h) { return hitTriangle(view.triangles, wr, prim, r, h); });
    return hit;
}

URBIS_HD inline Hit intersectClosest(const TriangleSceneView& view, Ray ray) { return traceTriangles(view, ray, false); }

/// Whether any triangle is hit with ray.tmin < t < ray.tmax (a shadow ray).
URBIS_HD inline bool occluded(const TriangleSceneView& view, Ray ray) { return traceTriangles(view, ray, true).valid(); }

} // namespace urbis
