// What a trace returns, and what the leaf dispatch keeps while it traverses (host+device).
#pragma once

#include "accel/bvh_traverse.h"
#include "geometry/triangle_intersect.h"
#include "math/frame.h"
#include "scene/prim_kinds.h"
#include "scene/scene_view.h"
#include "scene/surface_part.h"

namespace urbis {

/// What shading needs of a hit, whatever the kind: procedural shading (lane markings, lit windows)
/// is a function of it. Fields a caller does not read cost the GPU nothing: traces are inlined.
struct SurfaceHit {
    uint32_t kind = kNoPrimKind;   ///< index into PrimKinds
    float t = 0;                   ///< distance along the ray, in units of |ray.dir|
    Vec3f position;                ///< world, metres: ray.origin + t ray.dir
    Vec3f normal;                  ///< unit geometric normal, facing against the ray
    /// Along the surface (perpendicular to normal), not unit: frame() makes it the shading frame's x,
    /// so that hits no shading frame is asked of cost no square root.
    Vec3f tangent;
    /// In the kind's own parameterisation: a triangle's barycentrics of p1 and p2, a wall's (u, v)
    /// in metres along it and up from its bottom, the ground's world (x, z).
    Vec2f uv;
    uint32_t material = 0;
    uint32_t object = 0;           ///< 0 for the ground, building index + 1 otherwise
    SurfacePart part = SurfacePart::Whole;
    uint32_t index = 0;            ///< of the record in its kind's array (which wall, which lamp; an emitting triangle's light: lights/light_sampler.h)

    URBIS_HD bool valid() const { return kind != kNoPrimKind; }
    /// The shading frame: z the normal, x the unit tangent.
    URBIS_HD Frame frame() const {
        const Vec3f x = normalize(tangent);
        return {x, cross(normal, x), normal};
    }
};

/// What a trace works out once per ray for every kind's intersector.
struct TraceRay {
    BvhRay bvh;
    WatertightRay watertight;

    URBIS_HD explicit TraceRay(const Ray& ray) : bvh(ray), watertight(ray, bvh.invDir) {}
};

/// The closest hit so far while the BVH is traversed: the leaf slot, the distance and what the
/// kind's intersector keeps for building the SurfaceHit afterwards.
struct PrimHit {
    uint32_t slot = 0xffffffffu;
    float t = 3.0e38f;
    float u = 0, v = 0;                       ///< a triangle's barycentrics; a forest's tree's cell (i, k)
    uint32_t material = 0;                    ///< a wall part's material
    uint32_t axis = 0;                        ///< a wall part's normal axis in wall space
    SurfacePart part = SurfacePart::Whole;    ///< a wall's part
    URBIS_HD bool valid() const { return slot != 0xffffffffu; }
};

/// A kind's intersector, specialised beside each kind's test in geometry/:
///   static bool intersect(const Record&, const TraceRay&, Ray& ray, PrimHit& hit, bool anyHit):
///     a hit with ray.tmin < t < ray.tmax fills hit (not its slot) and sets ray.tmax = t;
///   static SurfaceHit surface(const SceneView&, uint32_t index, const Record&, const PrimHit&, const Ray&):
///     the hit as a SurfaceHit (normal not yet turned towards the ray);
///   using Emitter = <a light kind of scene/light_records.h>, where the kind emits (pbrt-v4's Le):
///     the light kind that says what a ray finds emitted at its hits (Emitter::emittedAt) and which
///     light of the list samples it (Emitter::lightAt). A kind without it shows its material's emission.
template <typename Record>
struct KindIntersector;

/// The point at distance t along a ray.
URBIS_HD inline Vec3f pointAt(const Ray& ray, float t) { return ray.origin + ray.dir * t; }

} // namespace urbis
