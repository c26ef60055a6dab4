// The parapet on a procedural wall's top (host+device): two faces in wall coordinates, its top (a
// trapezoid between the wall plane and the deck's edge, mitred where the neighbouring walls'
// parapets meet it) and its inner face down to the deck. The triangle twin meshes the top's corners
// and the inner face's quad; the intersector tests the same faces.
#pragma once

#include "geometry/wall_parts.h"

namespace urbis {

/// The corners of the parapet's top in wall coordinates (u, v, w), counter-clockwise seen from
/// above, the wall plane's first.
struct ParapetTop {
    Vec3f corners[4];
};

URBIS_HD inline ParapetTop parapetTop(const WallRecord& wall) {
    const float h = wall.height, w = -wall.parapetThickness;
    return {{{0, h, 0}, {wall.width, h, 0}, {wall.parapetInner1, h, w}, {wall.parapetInner0, h, w}}};
}

/// The parapet's inner face, from the deck up, as a cell part: the same quad for the intersector
/// and the twin.
URBIS_HD inline WallPart parapetInnerFace(const WallRecord& wall) {
    const float w = -wall.parapetThickness;
    return {{wall.parapetInner0, wall.height - wall.parapetHeight, w}, {wall.parapetInner1, wall.height, w}, 2,
            SurfacePart::Facade, wall.wallMaterial};
}

/// u of the parapet's top edge at wall depth w (in [-thickness, 0]): its start and end, along the
/// mitres from the wall's ends (w = 0) to the inner face's ends.
URBIS_HD inline void parapetSpanAt(const WallRecord& wall, float w, float& start, float& end) {
    const float depth = exactDiv(-w, wall.parapetThickness);
    start = wall.parapetInner0 * depth;
    end = exactMulAdd(wall.parapetInner1 - wall.width, depth, wall.width);
}

} // namespace urbis
