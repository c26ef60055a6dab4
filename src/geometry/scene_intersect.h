// Closest-hit and shadow queries over every primitive kind of a scene (host+device): one 8-wide BVH whose
// leaves the kinds' intersectors test (prim_dispatch.h), so new kinds join without touching the
// integrators.
#pragma once

#include "accel/wide_bvh_traverse.h"
#include "geometry/prim_dispatch.h"

namespace urbis {

#if URBIS_HAVE_SSE
using SceneLanes = WideLanesSse;
#else
using SceneLanes = WideLanesScalar;   // the GPU, and CPUs without SSE
#endif

#if URBIS_HAVE_SSE
/// traceScene without deferral, its lanes tested by WideLanesAvx2, in one function compiled for AVX2
/// (scene_intersect_avx2.cpp): only where the view's isa (hostWideIsa) says the CPU has it.
SurfaceHit traceSceneAvx2(const SceneView& scene, const Ray& ray, bool anyHit);
#endif

/// The closest surface along `ray` within (tmin, tmax), or with anyHit (a shadow ray) the first
/// one found: then only valid() means anything (blocked). The scene's 8-wide BVH (traverseWideBvh)
/// reaches each leaf position's kind-grouped slot through leafSlots. Cheap kinds (triangles, the
/// ground) are tested where the traversal meets them; costly ones (walls, each alone in a leaf marked
/// kWideCostlyLeaf) when they are the nearest item left or, with Defer (the GPU's default), once every
/// traversing lane of the warp holds one. Both find the same hit, and every Lanes the same hit bit for
/// bit. One function for both queries, so that the GPU path tracer inlines the traversal and the wall
/// intersector once: two copies overflowed the GPU's instruction cache. A scene without costly leaves takes a traversal
/// without their machinery; a scene runs one of the two, so only that one's code is fetched.
template <bool Defer = URBIS_GPU_CODE, typename Lanes = SceneLanes>
URBIS_HD inline SurfaceHit traceScene(const SceneView& scene, Ray ray, bool anyHit) {
#if URBIS_HAVE_SSE
    if constexpr (!Defer && std::is_same_v<Lanes, SceneLanes>)
        if (scene.isa == WideIsa::Avx2) return traceSceneAvx2(scene, ray, anyHit);
#endif
    const TraceRay tr(ray);
    PrimHit hit;
    auto testCheap = [&](uint32_t leaf, Ray& r, PrimHit& h) {
        return intersectSlot<KindFilter::Cheap>(scene, tr, scene.leafSlots[leaf], r, h, anyHit);
    };
    auto testCostly = [&](uint32_t leaf, Ray& r, PrimHit& h) {
        return intersectSlot<KindFilter::Costly>(scene, tr, scene.leafSlots[leaf], r, h, anyHit);
    };
    if (scene.costlyLeaves)
        traverseWideBvh<Lanes, true, Defer>(scene.nodes.data, tr.bvh, ray, hit, anyHit, testCheap, testCostly);
    else traverseWideBvh<Lanes>(scene.nodes.data, tr.bvh, ray, hit, anyHit, testCheap);
    if (!hit.valid()) return {};
    SurfaceHit out;
    if (anyHit) {
        out.kind = 0;   // blocked: nothing else is read
        return out;
    }
    out = surfaceOf(scene, hit, ray);
    if (dot(out.normal, ray.dir) > 0.0f) out.normal = -out.normal;
    // -0 + 0 is +0: signed zeros differ between a wall's exact axes and its twin's cross products, and
    // the shading frame (Frame::fromZ) branches on the sign of z, so both would sample differently.
    out.normal = {exactAdd(out.normal.x, 0.0f), exactAdd(out.normal.y, 0.0f), exactAdd(out.normal.z, 0.0f)};
    return out;
}

/// The closest surface along `ray` within (tmin, tmax).
URBIS_HD inline SurfaceHit intersectScene(const SceneView& scene, Ray ray) { return traceScene(scene, ray, false); }

/// Whether anything blocks `ray` within (tmin, tmax).
URBIS_HD inline bool occludedScene(const SceneView& scene, const Ray& ray) { return traceScene(scene, ray, true).valid(); }

} // namespace urbis
