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
        SurfaceHit s;
        s.t = hit.t;
        s.position = pointAt(ray, hit.t);
        const Vec3f edge = tri.p1 - tri.p0;
        s.normal = normalize(cross(edge, tri.p2 - tri.p0));
        s.tangent = normalize(edge);
        s.uv = {hit.u, hit.v};
        s.material = info.material;
        s.object = info.object;
        s.part = SurfacePart(info.part);
        return s;
    }
};

} // namespace urbis
