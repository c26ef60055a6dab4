#include "scene/lamp_record.h"

#include "scene/lamp_pieces.h"

#include <cmath>

namespace urbis {

namespace {

/// A piece's box in lamp coordinates.
Bounds3f pieceBounds(const LampPiece& p) {
    switch (p.shape) {
    case LampPieceShape::Frustum: {
        const float r = std::fmax(p.b.y, p.highRadius());
        Vec3f lo = p.a - Vec3f{r, r, r}, hi = p.a + Vec3f{r, r, r};
        lo[p.axis] = p.a[p.axis];
        hi[p.axis] = p.a[p.axis] + p.b.x;
        return {lo, hi};
    }
    case LampPieceShape::Sphere: {
        const float r = p.b.x;
        return {{p.a.x - r, std::fmax(p.a.y - r, p.b.y), p.a.z - r}, p.a + Vec3f{r, r, r}};
    }
    case LampPieceShape::None: break;
    }
    return {};
}

} // namespace

Bounds3f primBounds(const LampRecord& lamp) {
    Bounds3f local;
    for (int i = 0; i < kLampPieces; ++i)
        if (const LampPiece p = lampPiece(lamp, i); p.shape != LampPieceShape::None) local.extend(pieceBounds(p));
    Bounds3f world;
    for (int corner = 0; corner < 8; ++corner)
        world.extend(lamp.worldFromLamp({corner & 1 ? local.hi.x : local.lo.x, corner & 2 ? local.hi.y : local.lo.y,
                                         corner & 4 ? local.hi.z : local.lo.z}));
    // The intersector rounds in lamp coordinates: a millimetre and a relative margin keep every hit inside.
    const float pad = 1e-3f + 1e-6f * maxComponent(vmax(vmax(world.hi, -world.hi), vmax(world.lo, -world.lo)));
    return {world.lo - Vec3f{pad, pad, pad}, world.hi + Vec3f{pad, pad, pad}};
}

} // namespace urbis
