// The parapet on a procedural wall's top (host+device): two faces in wall coordinates, its top (a
// trapezoid between the wall plane and the deck's edge, mitred where the neighbouring walls'
// parapets meet it) and its inner face down to the deck. The triangle twin meshes the corners below;
// the intersector tests the same faces as plane crossings.
#pragma once

#include "geometry/wall_record.h"

namespace urbis {

/// The corners of a wall's parapet in wall coordinates (u, v, w): `top` counter-clockwise seen from
/// above (wall plane first), `inner` the inner face (bottom edge first).
struct ParapetCorners {
    Vec3f top[4];
    Vec3f inner[4];
};

URBIS_HD inline ParapetCorners parapetCorners(const WallRecord& wall) {
    const float h = wall.height, deck = wall.height - wall.parapetHeight, w = -wall.parapetThickness;
    const float a = wall.parapetInner0, b = wall.parapetInner1;
    return {{{0, h, 0}, {wall.width, h, 0}, {b, h, w}, {a, h, w}}, {{a, deck, w}, {b, deck, w}, {b, h, w}, {a, h, w}}};
}

/// u of the parapet's top edge at wall depth w (in [-thickness, 0]): its start and end, along the
/// mitres from the wall's ends (w = 0) to the inner face's ends.
URBIS_HD inline float parapetStartAt(const WallRecord& wall, float w) {
    return wall.parapetInner0 * (-w / wall.parapetThickness);
}
URBIS_HD inline float parapetEndAt(const WallRecord& wall, float w) {
    return wall.width + (wall.parapetInner1 - wall.width) * (-w / wall.parapetThickness);
}

} // namespace urbis
