// The lamp kind's intersector for the leaf dispatch (host+device): the analytic lamp test.
#pragma once

#include "geometry/lamp_intersect.h"
#include "geometry/surface_hit.h"
#include "math/constants.h"
#include "scene/light_records.h"

namespace urbis {

template <>
struct KindIntersector<LampRecord> {
    using Emitter = LampLight;  ///< its glass shows its lamp's light (lights/lamp_light.h)

    URBIS_HD static bool intersect(const LampRecord& lamp, const TraceRay&, Ray& ray, PrimHit& hit, bool anyHit) {
        LampHit l;
        if (!intersectLamp(lamp, ray, l, anyHit)) return false;
        hit.t = l.t;
        hit.axis = l.piece * 4 + l.face;
        ray.tmax = l.t;
        return true;
    }
    /// uv: for a frustum, how far along its axis and the angle around it (turns, from the arm's
    /// side); for the sphere, the height above its centre and the angle.
    URBIS_HD static SurfaceHit surface(const SceneView&, uint32_t, const LampRecord& lamp, const PrimHit& hit,
                                       const Ray& ray) {
        const LampPiece piece = lampPiece(lamp, int(hit.axis / 4));
        const Vec3f p = pointAt(ray, hit.t), rel = p - lamp.base;
        const Vec3f arm = lamp.armAxis(), side = lamp.sideAxis();
        const Vec3f q{dot(rel, arm), rel.y, dot(rel, side)};
        const Vec3f n = lampPieceNormal(piece, q, hit.axis % 4);
        const Vec3f normal = arm * n.x + Vec3f{0, n.y, 0} + side * n.z;
        // Around the piece's axis (the arm's for the arm, else up); across the arm on caps that face it.
        const Vec3f axisDir = piece.axis == 0 ? arm : Vec3f{0, 1, 0};
        const Vec3f around = cross(axisDir, normal);
        const Vec3f tangent = dot(around, around) > 1e-12f ? around : side;
        const Vec3f d = q - piece.a;
        const int rx = piece.axis == 0 ? 1 : 0;
        const Vec2f uv{d[piece.axis], atan2f(d.z, d[rx]) * (0.5f / kPi) + 0.5f};
        const uint32_t material = lamp.material + uint32_t(piece.material);
        return {kNoPrimKind, hit.t, p, normal, tangent, uv, material, lamp.object, piece.part};
    }
};

} // namespace urbis
