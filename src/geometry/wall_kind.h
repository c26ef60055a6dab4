// The wall kind's intersector for the leaf dispatch (host+device): the procedural wall test.
#pragma once

#include "geometry/surface_hit.h"
#include "geometry/wall_intersect.h"

namespace urbis {

template <>
struct KindIntersector<WallRecord> {
    URBIS_HD static bool intersect(const WallRecord& wall, const TraceRay& tr, Ray& ray, PrimHit& hit, bool anyHit) {
        WallHit w;
        if (!intersectWall(wall, ray, w, anyHit, tr.bvh.invDir[1])) return false;
        hit.t = w.t;
        hit.axis = w.axis;
        hit.material = w.material;
        hit.part = w.part;
        ray.tmax = w.t;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView&, uint32_t, const WallRecord& wall, const PrimHit& hit,
                                       const Ray& ray) {
        SurfaceHit s;
        s.t = hit.t;
        s.position = pointAt(ray, hit.t);
        s.normal = wallAxisNormal(wall, hit.axis);
        s.tangent = hit.axis == 0 ? wall.normal : wall.axisU;
        const Vec3f rel = s.position - wall.origin;
        s.uv = {dot(rel, wall.axisU), rel.y};
        s.material = hit.material;
        s.object = wall.object;
        s.part = hit.part;
        return s;
    }
};

} // namespace urbis
