// The triangle kind's intersector for the leaf dispatch (host+device): the watertight test.
#pragma once

#include "geometry/surface_hit.h"
#include "geometry/triangle_intersect.h"

namespace urbis {

template <>
struct KindIntersector<Triangle> {
    URBIS_HD static bool intersect(const Triangle& tri, const TraceRay& tr, Ray& ray, PrimHit& hit, bool) {
        float t, u, v;
        if (!intersectTriangle(tri, ray, tr.watertight, t, u, v)) return false;
        hit.t = t;
        hit.u = u;
        hit.v = v;
        ray.tmax = t;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView& scene, uint32_t index, const Triangle& tri, const PrimHit& hit,
                                       const Ray& ray) {
        const TriangleInfo info = scene.triangleInfo[index];
        const Vec3f edge = tri.p1 - tri.p0;
        return {kNoPrimKind, hit.t, pointAt(ray, hit.t), normalize(cross(edge, tri.p2 - tri.p0)), edge, {hit.u, hit.v},
                info.material, info.object, SurfacePart(info.part)};
    }
};

} // namespace urbis
