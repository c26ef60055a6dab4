// Closest-hit and shadow queries against triangles over an 8-wide compressed BVH (host+device).
#pragma once

#include "accel/wide_bvh_traverse.h"
#include "geometry/triangle_block_intersect.h"
#include "geometry/triangle_block_sse.h"
#include "scene/triangle_scene_view.h"

#include <cstdint>

namespace urbis {

/// The closest triangle hit with ray.tmin < t < ray.tmax (anyHit false), or the first one found in
/// any order (anyHit true: a shadow ray), in world space, over a WideTriangleSceneView: watertight
/// (Woop et al. 2013) and robust in the BVH (Ize 2013). Its node lanes are tested by `Lanes`
/// (WideLanesScalar, WideLanesSse; WideLanesAvx2 in traceWideTrianglesAvx2) and its leaves' blocks by
/// `Leaf` (TriangleBlockScalar, TriangleBlockSse): the same hits, bit for bit, for each. Hit::prim
/// indexes view.triangles (leaf order); invalid if nothing is hit.
template <typename Lanes, typename Leaf>
URBIS_HD inline Hit traceWideTriangles(const WideTriangleSceneView& view, Ray ray, bool anyHit) {
    const BvhRay br(ray);
    const WatertightRay wr(ray, br.invDir);
    Hit hit;
    traverseWideBvh<Lanes>(view.nodes, br, ray, hit, anyHit,
                           [&](uint32_t block, Ray& r, Hit& h) { return Leaf::hit(view.blocks[block], wr, r, h); });
    return hit;
}

#if URBIS_HAVE_SSE
/// traceWideTriangles with WideLanesAvx2 and TriangleBlockSse, compiled for AVX2
/// (wide_triangle_scene_avx2.cpp): call only where hostWideIsa() says the CPU has it.
Hit traceWideTrianglesAvx2(const WideTriangleSceneView& view, Ray ray, bool anyHit);
#endif

/// traceWideTriangles in the instruction set `isa` (host): its lane test, and the SSE block test on x86.
inline Hit traceWideTriangles(WideIsa isa, const WideTriangleSceneView& view, const Ray& ray, bool anyHit) {
#if URBIS_HAVE_SSE
    if (isa == WideIsa::Avx2) return traceWideTrianglesAvx2(view, ray, anyHit);
    if (isa == WideIsa::Sse) return traceWideTriangles<WideLanesSse, TriangleBlockSse>(view, ray, anyHit);
#endif
    return traceWideTriangles<WideLanesScalar, TriangleBlockScalar>(view, ray, anyHit);
}

} // namespace urbis
