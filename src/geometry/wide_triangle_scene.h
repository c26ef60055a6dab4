// Closest-hit and shadow queries against triangles over an 8-wide compressed BVH (host+device).
#pragma once

#include "accel/wide_bvh_traverse.h"
#include "geometry/triangle_scene.h"
#include "scene/triangle_scene_view.h"

#include <cstdint>

namespace urbis {

/// traceTriangles (triangle_scene.h) over a WideBvh, its lanes tested by `Lanes` (WideLanesScalar,
/// WideLanesSse; traceWideTrianglesAvx2): the same hits for each. Hit::prim indexes view.triangles
/// (leaf order).
template <typename Lanes>
URBIS_HD inline Hit traceWideTriangles(const WideTriangleSceneView& view, Ray ray, bool anyHit) {
    const BvhRay br(ray);
    const WatertightRay wr(ray, br.invDir);
    Hit hit;
    traverseWideBvh<Lanes>(view.nodes, br, ray, hit, anyHit,
                           [&](uint32_t prim, Ray& r, Hit& h) { return hitTriangle(view.triangles, wr, prim, r, h); });
    return hit;
}

#if URBIS_HAVE_SSE
/// traceWideTriangles with WideLanesAvx2, compiled for AVX2 (wide_triangle_scene_avx2.cpp): call
/// only where hostWideIsa() says the CPU has it.
Hit traceWideTrianglesAvx2(const WideTriangleSceneView& view, Ray ray, bool anyHit);
#endif

/// traceWideTriangles with the lane test of `isa` (host).
inline Hit traceWideTriangles(WideIsa isa, const WideTriangleSceneView& view, const Ray& ray, bool anyHit) {
#if URBIS_HAVE_SSE
    if (isa == WideIsa::Avx2) return traceWideTrianglesAvx2(view, ray, anyHit);
    if (isa == WideIsa::Sse) return traceWideTriangles<WideLanesSse>(view, ray, anyHit);
#endif
    return traceWideTriangles<WideLanesScalar>(view, ray, anyHit);
}

} // namespace urbis
