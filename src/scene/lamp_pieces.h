// The analytic pieces of a street lamp (host+device), in lamp coordinates (LampRecord): the pole, the
// arm, the head's housing and its glass, each a truncated cone (a cylinder when both radii agree, a
// disc when it has caps only) or a sphere cut by a horizontal plane. The intersector tests
// them, primBounds bounds them and the triangle twin tessellates them, all from this one layout, so
// the two representations cannot drift apart. Proportions follow common street lamps: a cobra head
// about 0.6 m long, a globe of 0.5 m, a lantern's glass widening upwards under a pointed roof.
#pragma once

#include "scene/lamp_record.h"
#include "scene/surface_part.h"

namespace urbis {

enum class LampPieceShape : uint8_t { None, Frustum, Sphere };

/// Which surfaces of a frustum exist: its side, the disc at its low end, the disc at its high end.
enum LampFaces : uint8_t { kLampSide = 1, kLampCapLow = 2, kLampCapHigh = 4 };

/// One piece, in lamp coordinates (u, y, w).
///   Frustum: axis 0 (along u) or 1 (up); a = the centre of its low end; b = (length, radius at
///            the low end, slope: the radius's change per metre along the axis); faces: LampFaces.
///   Sphere:  a = the centre; b = (radius, lowest y kept, unused): open below that plane; faces kLampSide.
/// What decides hits, so every multiply-add here is one of urbis.h's exact operations: nvcc would
/// otherwise fuse `u + 0.5f * s` and place the device's pieces a rounding away from the host's.
struct LampPiece {
    LampPieceShape shape = LampPieceShape::None;
    uint8_t axis = 1;
    uint8_t faces = 0;
    SurfacePart part = SurfacePart::LampPole;
    LampMaterial material = LampMaterial::Metal;
    Vec3f a, b;

    /// A frustum's radius at its high end.
    URBIS_HD float highRadius() const { return exactMulAdd(b.z, b.x, b.y); }
};

/// Pieces per lamp: pole, arm, housing, glass (a lamp without a pole or an arm leaves theirs None).
inline constexpr int kLampPieces = 4;

/// How a pole narrows: 5 mm of radius per metre up (a 6 m pole of 7 cm ends at 4 cm).
inline constexpr float kLampPoleSlope = -0.005f;

/// The arm's radius: half the pole's at its foot, and 3 cm where the lamp has no pole.
URBIS_HD inline float lampArmRadius(const LampRecord& l) { return l.poleRadius > 0.0f ? 0.5f * l.poleRadius : 0.03f; }

/// Height of the head's shape, in units of headSize.
URBIS_HD inline float lampHeadHeight(LampShape s) {
    switch (s) {
    case LampShape::Cobra: return 0.3f;
    case LampShape::Globe: return 1.05f;
    case LampShape::Lantern: return 0.8f;
    case LampShape::Cone: return 0.3f;
    case LampShape::Flat: return 0.08f;
    }
    return 0.0f;
}

/// y of the head's bottom: on the pole's top for a post-top lamp; on an arm, a cobra head is
/// centred on the arm's axis and the others hang below it.
URBIS_HD inline float lampHeadBottom(const LampRecord& l) {
    const float headHeight = exactMul(lampHeadHeight(l.shape), l.headSize);
    if (l.armLength <= 0.0f) return l.height;
    if (l.shape == LampShape::Cobra) return exactMulAdd(-0.5f, headHeight, l.height);
    return exactSub(exactSub(l.height, lampArmRadius(l)), headHeight);
}

/// A head piece in units of headSize about the head's centre (u = armLength) and bottom: the
/// piece's a as an offset; b a frustum's (length, radius, slope) with the slope as it is, a sphere's
/// (radius, cut above the bottom, unused).
struct LampHeadLayout {
    LampPieceShape shape;
    uint8_t axis;
    uint8_t faces;
    SurfacePart part;
    LampMaterial material;
    Vec3f a, b;
};

/// The head's housing (index 0) or glass (index 1) of each shape, as constants: one table-like
/// switch and one scaling below keep the GPU's code small.
URBIS_HD inline LampHeadLayout lampHeadLayout(LampShape shape, int index) {
    constexpr LampPieceShape frustum = LampPieceShape::Frustum;
    constexpr SurfacePart head = SurfacePart::LampHead, glass = SurfacePart::LampGlass;
    constexpr LampMaterial housing = LampMaterial::Housing, pane = LampMaterial::Glass;
    constexpr uint8_t sideLow = kLampSide | kLampCapLow;
    const bool h = index == 0;
    switch (shape) {
    case LampShape::Cobra:   // a housing along the arm, widening to its end, its glass a disc under it
        return h ? LampHeadLayout{frustum, 0, sideLow | kLampCapHigh, head, housing, {-0.45f, 0.15f, 0}, {0.95f, 0.1f, 0.05f}}
                 : LampHeadLayout{frustum, 1, kLampCapLow, glass, pane, {0.15f, 0.0f, 0}, {0.0f, 0.1f, 0.0f}};
    case LampShape::Globe:   // a collar, and a glass sphere cut where it sits on the collar
        return h ? LampHeadLayout{frustum, 1, sideLow, head, housing, {0, 0.0f, 0}, {0.1f, 0.25f, -0.2f}}
                 : LampHeadLayout{LampPieceShape::Sphere, 1, kLampSide, glass, pane, {0, 0.55f, 0}, {0.5f, 0.1f, 0}};
    case LampShape::Lantern: // glass widening upwards, under a pointed roof
        return h ? LampHeadLayout{frustum, 1, sideLow, head, housing, {0, 0.55f, 0}, {0.25f, 0.34f, -1.16f}}
                 : LampHeadLayout{frustum, 1, sideLow, glass, pane, {0, 0.0f, 0}, {0.55f, 0.16f, 0.18f}};
    case LampShape::Cone:    // a conical shade, open below, its glass a disc inside the rim
        return h ? LampHeadLayout{frustum, 1, kLampSide | kLampCapHigh, head, housing, {0, 0.0f, 0}, {0.3f, 0.5f, -1.27f}}
                 : LampHeadLayout{frustum, 1, kLampCapLow, glass, pane, {0, 0.02f, 0}, {0.0f, 0.46f, 0.0f}};
    case LampShape::Flat:    // a flat round housing, its glass a disc just under it
        return h ? LampHeadLayout{frustum, 1, sideLow | kLampCapHigh, head, housing, {0, 0.0f, 0}, {0.08f, 0.5f, 0.0f}}
                 : LampHeadLayout{frustum, 1, kLampCapLow, glass, pane, {0, -0.02f, 0}, {0.0f, 0.42f, 0.0f}};
    }
    return {};
}

/// The head's housing (index 0) or glass (index 1) of a lamp.
URBIS_HD inline LampPiece lampHeadPiece(const LampRecord& l, int index) {
    const LampHeadLayout k = lampHeadLayout(l.shape, index);
    const float s = l.headSize, u = l.armLength, bottom = lampHeadBottom(l);
    const bool sphere = k.shape == LampPieceShape::Sphere;
    return {k.shape, k.axis, k.faces, k.part, k.material,
            {exactMulAdd(s, k.a.x, u), exactMulAdd(s, k.a.y, bottom), exactMul(s, k.a.z)},
            {exactMul(s, k.b.x), exactMulAdd(s, k.b.y, sphere ? bottom : 0.0f), k.b.z}};
}

/// Piece `index` (0 .. kLampPieces - 1) of a lamp: 0 the pole (up to the arm's top or the head's
/// bottom), 1 the arm, 2 the head's housing, 3 its glass.
URBIS_HD inline LampPiece lampPiece(const LampRecord& l, int index) {
    const float armRadius = lampArmRadius(l);
    if (index == 0) {
        if (l.poleRadius <= 0.0f) return {};
        const float top = l.armLength > 0.0f ? exactAdd(l.height, armRadius) : l.height;
        return {LampPieceShape::Frustum, 1, kLampSide | kLampCapHigh, SurfacePart::LampPole, LampMaterial::Metal,
                {0, 0, 0}, {top, l.poleRadius, kLampPoleSlope}};
    }
    if (index == 1) {
        if (l.armLength <= 0.0f) return {};
        const uint8_t faces = kLampSide | kLampCapHigh | (l.poleRadius > 0.0f ? 0 : kLampCapLow);
        return {LampPieceShape::Frustum, 0, faces, SurfacePart::LampPole, LampMaterial::Metal, {0, l.height, 0},
                {l.armLength, armRadius, 0.0f}};
    }
    return lampHeadPiece(l, index - 2);
}

} // namespace urbis
