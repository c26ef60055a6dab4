// Ray/ground intersection (host+device): the plane y = height within the record's rectangle.
#pragma once

#include "geometry/surface_hit.h"
#include "scene/ground_record.h"

namespace urbis {

/// Whether `ray` meets the ground from above with ray.tmin < t < ray.tmax: then t. `invDirY`: BvhRay's
/// safeInverse(ray.dir.y). Exact (urbis.h): it decides hits. Rays going up pass it: below the ground
/// lie only the beds of water (docs/water.md), whose light comes up through it.
URBIS_HD inline bool intersectGround(const GroundRecord& g, const Ray& ray, float invDirY, float& t) {
    if (!(ray.dir.y < 0.0f)) return false;
    const float hitT = (g.height - ray.origin.y) * invDirY;
    if (!(hitT > ray.tmin && hitT < ray.tmax)) return false;
    const float x = exactMulAdd(hitT, ray.dir.x, ray.origin.x), z = exactMulAdd(hitT, ray.dir.z, ray.origin.z);
    if (!(x >= g.x0 && x <= g.x1 && z >= g.z0 && z <= g.z1)) return false;
    t = hitT;
    return true;
}

template <>
struct KindIntersector<GroundRecord> {
    URBIS_HD static bool intersect(const GroundRecord& g, const TraceRay& tr, Ray& ray, PrimHit& hit, bool) {
        float t;
        if (!intersectGround(g, ray, tr.bvh.invDir[1], t)) return false;
        hit.t = t;
        ray.tmax = t;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView&, uint32_t, const GroundRecord& g, const PrimHit& hit,
                                       const Ray& ray) {
        const Vec3f p = pointAt(ray, hit.t);
        return {kNoPrimKind, hit.t, p, {0, 1, 0}, {1, 0, 0}, {p.x, p.z}, g.material, 0, SurfacePart::Whole};
    }
};

} // namespace urbis
