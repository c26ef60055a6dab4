// Closest-hit and shadow queries against triangles over an 8-wide compressed BVH (host+device).
#pragma once

#include "accel/wide_bvh_traverse.h"
#include "geometry/triangle_intersect.h"
#include "scene/triangle_scene_view.h"

#include <cstdint>

namespace urbis {

/// traceTriangles (triangle_scene.h) over a WideBvh, its lanes tested with `Isa`: the same hits for
/// every Isa. Hit::prim indexes view.triangles (leaf order).
template <WideIsa Isa>
URBIS_HD inline Hit traceWideTriangles(const WideTriangleSceneView& view, Ray ray, bool anyHit) {
    const BvhRay br(ray);
    const WatertightRay wr(ray, br.invDir);
    Hit hit;
    traverseWideBvh<Isa>(view.nodes, br, ray, hit, anyHit, [&](uint32_t prim, Ray& r, Hit& h) {
        float t, u, v;
        if (!intersectTriangle(view.triangles[prim], r, wr, t, u, v)) return false;
        h = {prim, t, u, v};
        r.tmax = t;
        return true;
    });
    return hit;
}

} // namespace urbis
