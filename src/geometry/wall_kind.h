// The wall kind's intersector for the leaf dispatch (host+device): the procedural wall test.
#pragma once

#include "geometry/surface_hit.h"
#include "geometry/wall_intersect.h"
#include "scene/light_records.h"

namespace urbis {

template <>
struct KindIntersector<WallRecord> {
    using Emitter = WindowLight;  ///< its lit rooms, the windows of its record as one light (lights/window_light.h)

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
        const Vec3f p = pointAt(ray, hit.t), rel = p - wall.origin;
        return {kNoPrimKind, hit.t, p, wallAxisNormal(wall, hit.axis), hit.axis == 0 ? wall.normal : wall.axisU,
                {dot(rel, wall.axisU), rel.y}, hit.material, wall.object, hit.part};
    }
};

} // namespace urbis
