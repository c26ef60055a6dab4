// The triangle kind's intersector for the leaf dispatch (host+device): the watertight test.
#pragma once

#include "geometry/road_markings.h"
#include "geometry/surface_hit.h"
#include "geometry/triangle_intersect.h"
#include "scene/light_records.h"

namespace urbis {

template <>
struct KindIntersector<Triangle> {
    using Emitter = EmissiveSurfaceLight;  ///< an emitting material's triangles are lights of their own (lights/emissive_surface_light.h)

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
        SurfaceHit out{kNoPrimKind, hit.t, pointAt(ray, hit.t), normalize(cross(edge, tri.p2 - tri.p0)), edge,
                       {hit.u, hit.v}, info.material, info.object, SurfacePart(info.part)};
        // A carriageway's object is its RoadSegment: uv becomes the road's (distance along, metres left),
        // and paint replaces the surface's material where a marking covers the hit.
        if (out.part == SurfacePart::Road && info.object < scene.roadSegments.size) {
            const RoadSegment& segment = scene.roadSegments[info.object];
            const Vec2f road = roadCoordinates(segment, out.position.x, out.position.z);
            const uint32_t paint = roadPaintAt(segment, road.x, road.y);
            out.uv = {segment.distance + road.x, road.y};
            out.object = segment.object;
            out.material = paint == kNoPaint ? info.material : segment.paint + paint - 1;
        }
        return out;
    }
};

} // namespace urbis
