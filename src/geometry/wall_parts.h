// The parts of one cell of a procedural wall, made on demand from the wall record and a hash of
// (building, wall, floor, slot): nothing per window is stored. Host+device; the procedural
// intersector and the triangle twin both call these, so the two representations agree.
#pragma once

#include "geometry/wall_record.h"
#include "math/hash.h"
#include "scene/surface_part.h"

namespace urbis {

/// An axis-aligned quad or box in wall coordinates (metres). A quad has lo[axis] == hi[axis].
struct WallPart {
    Vec3f lo, hi;
    uint8_t axis = 0;        ///< a quad's normal axis (0: u, 1: v, 2: w), or kWallPartBox
    SurfacePart part = SurfacePart::Facade;
    uint32_t material = 0;
};

/// WallPart::axis of a box.
inline constexpr uint8_t kWallPartBox = 3;
/// The most parts a cell (or the margins) can have.
inline constexpr int kMaxCellParts = 24;

/// Per-window choices, the same for every ray: 1 in this many rooms is lit (by day: emissive).
inline constexpr float kLitRoomChance = 0.3f;
/// Chance that a cell of a wall with balconies holds one (above the ground floor).
inline constexpr float kBalconyChance = 0.5f;
/// Chance that a ground-floor cell of a shop-front wall holds a shop window (as in the thesis).
inline constexpr float kShopWindowChance = 0.8f;

/// Which parts of a cell a ray can reach first. The glass (or curtain-wall panel) plane closes every
/// cell: a ray in front of it can only reach the parts in front (frame, jambs, glass, balcony,
/// mullions), a ray behind it only those behind (room with its front wall, glass, mullions).
enum class CellSide : uint8_t { Both, Front, Back };

/// Fixed-size list of parts. The functions below write parts to any `Out` with this addQuad and
/// addBox: a CellParts (the twin, tests), or the intersector's part tester, which tests each part
/// as it is made instead of keeping ~770 bytes of parts on the stack (GPU local memory).
struct CellParts {
    WallPart parts[kMaxCellParts];
    int count = 0;

    URBIS_HD void addQuad(uint8_t axis, Vec3f lo, Vec3f hi, SurfacePart part, uint32_t material) {
        parts[count++] = WallPart{lo, hi, axis, part, material};
    }
    URBIS_HD void addBox(Vec3f lo, Vec3f hi, SurfacePart part, uint32_t material) {
        parts[count++] = WallPart{lo, hi, kWallPartBox, part, material};
    }
};

/// The plain margins of a wall around its cell grid, as quads in the plane w = 0 (left, right,
/// bottom, top; empty ones left out).
template <class Out>
URBIS_HD inline void marginParts(const WallRecord& wall, Out& out) {
    const float u0 = wall.gridU, u1 = wall.gridU + wall.gridWidth();
    const float v0 = wall.gridV, v1 = wall.gridV + wall.gridHeight();
    const uint32_t m = wall.wallMaterial;
    if (u0 > 0.0f) out.addQuad(2, {0, 0, 0}, {u0, wall.height, 0}, SurfacePart::Facade, m);
    if (u1 < wall.width) out.addQuad(2, {u1, 0, 0}, {wall.width, wall.height, 0}, SurfacePart::Facade, m);
    if (v0 > 0.0f) out.addQuad(2, {u0, 0, 0}, {u1, v0, 0}, SurfacePart::Facade, m);
    if (v1 < wall.height) out.addQuad(2, {u0, v1, 0}, {u1, wall.height, 0}, SurfacePart::Facade, m);
}

/// The hash that every choice of one cell draws from.
URBIS_HD inline HashStream cellRandom(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    return HashStream{hash3(hash2(wall.seed, wall.wallIndex), floor, slot)};
}

/// The room behind an opening: five quads (back, two sides, floor, ceiling) inset from the cell
/// [u0, u1] x [v0, v1] by a thin inner wall, from w = -depthBack to w = front.
template <class Out>
URBIS_HD inline void addRoom(const WallRecord& wall, float u0, float u1, float v0, float v1, float front,
                             uint32_t material, CellSide side, Out& out) {
    if (side == CellSide::Front) return;
    constexpr float kInset = 0.05f;
    const float a = u0 + kInset, b = u1 - kInset, c = v0 + kInset, d = v1 - kInset, back = -wall.depthBack;
    out.addQuad(2, {a, c, back}, {b, d, back}, SurfacePart::Room, material);
    out.addQuad(0, {a, c, back}, {a, d, front}, SurfacePart::Room, material);
    out.addQuad(0, {b, c, back}, {b, d, front}, SurfacePart::Room, material);
    out.addQuad(1, {a, c, back}, {b, c, front}, SurfacePart::Room, material);
    out.addQuad(1, {a, d, back}, {b, d, front}, SurfacePart::Room, material);
}

/// The plane w = `w` of the cell [u0, u1] x [v0, v1] around the opening [ou0, ou1] x [ov0, ov1]: four quads.
template <class Out>
URBIS_HD inline void addFrame(float u0, float u1, float v0, float v1, float ou0, float ou1, float ov0, float ov1, float w,
                              SurfacePart part, uint32_t material, Out& out) {
    out.addQuad(2, {u0, v0, w}, {ou0, v1, w}, part, material);
    out.addQuad(2, {ou1, v0, w}, {u1, v1, w}, part, material);
    out.addQuad(2, {ou0, v0, w}, {ou1, ov0, w}, part, material);
    out.addQuad(2, {ou0, ov1, w}, {ou1, v1, w}, part, material);
}

/// A recessed opening [ou0, ou1] x [ov0, ov1] in the cell [u0, u1] x [v0, v1]: the wall plane around
/// it and its jambs (front), the glass `reveal` metres deep (both sides) and the room behind, whose
/// front wall lies in the glass plane (back).
template <class Out>
URBIS_HD inline void addOpening(const WallRecord& wall, float u0, float u1, float v0, float v1, float ou0, float ou1,
                                float ov0, float ov1, uint32_t roomMaterial, CellSide side, Out& out) {
    const uint32_t m = wall.wallMaterial;
    const float r = -wall.reveal;
    if (side != CellSide::Back) {
        addFrame(u0, u1, v0, v1, ou0, ou1, ov0, ov1, 0.0f, SurfacePart::Facade, m, out);
        out.addQuad(0, {ou0, ov0, r}, {ou0, ov1, 0}, SurfacePart::Jamb, m);
        out.addQuad(0, {ou1, ov0, r}, {ou1, ov1, 0}, SurfacePart::Jamb, m);
        out.addQuad(1, {ou0, ov0, r}, {ou1, ov0, 0}, SurfacePart::Jamb, m);
        out.addQuad(1, {ou0, ov1, r}, {ou1, ov1, 0}, SurfacePart::Jamb, m);
    }
    out.addQuad(2, {ou0, ov0, r}, {ou1, ov1, r}, SurfacePart::Glass,
                wall.facadeMaterials + uint32_t(FacadeMaterial::Glass));
    if (side != CellSide::Front) addFrame(u0, u1, v0, v1, ou0, ou1, ov0, ov1, r, SurfacePart::Room, roomMaterial, out);
    addRoom(wall, u0, u1, v0, v1, r, roomMaterial, side, out);
}

/// A balcony in front of the cell's opening [ou0, ou1]: a slab on the cell's floor and a railing
/// (front and two sides) around it, depthFront metres deep.
template <class Out>
URBIS_HD inline void addBalcony(const WallRecord& wall, float u0, float u1, float v0, float ou0, float ou1,
                                CellSide side, Out& out) {
    if (side == CellSide::Back) return;
    constexpr float kSlab = 0.15f, kRail = 0.05f, kRailHeight = 1.0f;
    const float a = fmaxf(u0 + 0.1f, ou0 - 0.6f), b = fminf(u1 - 0.1f, ou1 + 0.6f), f = wall.depthFront;
    const uint32_t slab = wall.facadeMaterials + uint32_t(FacadeMaterial::Slab);
    const uint32_t rail = wall.facadeMaterials + uint32_t(FacadeMaterial::Railing);
    const float top = v0 + kSlab, railTop = top + kRailHeight;
    out.addBox({a, v0, 0}, {b, top, f}, SurfacePart::BalconySlab, slab);
    out.addBox({a, top, f - kRail}, {b, railTop, f}, SurfacePart::Railing, rail);
    out.addBox({a, top, 0}, {a + kRail, railTop, f - kRail}, SurfacePart::Railing, rail);
    out.addBox({b - kRail, top, 0}, {b, railTop, f - kRail}, SurfacePart::Railing, rail);
}

/// A curtain-wall panel filling the cell: half mullions on its four edges, a spandrel below
/// wall.sillHeight and glass above it, both `reveal` deep, and the room behind.
template <class Out>
URBIS_HD inline void addCurtainPanel(const WallRecord& wall, float u0, float u1, float v0, float v1,
                                     uint32_t roomMaterial, CellSide side, Out& out) {
    constexpr float kHalfMullion = 0.06f, kMullionDepth = 0.12f;
    const float r = -wall.reveal, m = kHalfMullion;
    const uint32_t mullion = wall.facadeMaterials + uint32_t(FacadeMaterial::Mullion);
    out.addBox({u0, v0, r}, {u0 + m, v1, kMullionDepth}, SurfacePart::Mullion, mullion);
    out.addBox({u1 - m, v0, r}, {u1, v1, kMullionDepth}, SurfacePart::Mullion, mullion);
    out.addBox({u0 + m, v0, r}, {u1 - m, v0 + m, kMullionDepth}, SurfacePart::Mullion, mullion);
    out.addBox({u0 + m, v1 - m, r}, {u1 - m, v1, kMullionDepth}, SurfacePart::Mullion, mullion);
    const float split = v0 + wall.sillHeight;
    out.addQuad(2, {u0 + m, v0 + m, r}, {u1 - m, split, r}, SurfacePart::Spandrel,
                wall.facadeMaterials + uint32_t(FacadeMaterial::Spandrel));
    out.addQuad(2, {u0 + m, split, r}, {u1 - m, v1 - m, r}, SurfacePart::Glass,
                wall.facadeMaterials + uint32_t(FacadeMaterial::Glass));
    addRoom(wall, u0, u1, v0, v1, r, roomMaterial, side, out);
}

/// What a punched cell holds, drawn from its hash: the cell's extent, its opening (window, balcony
/// door or shop window) and the room's material.
struct CellLayout {
    float u0, u1, v0, v1;        ///< the cell
    float ou0, ou1, ov0, ov1;    ///< the opening (punched walls)
    uint32_t roomMaterial;
    bool balcony;
};

/// The layout of cell (floor, slot) of `wall`.
URBIS_HD inline CellLayout cellLayout(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    CellLayout c;
    c.u0 = wall.gridU + wall.slotWidth * float(slot);
    c.u1 = c.u0 + wall.slotWidth;
    c.v0 = wall.gridV + wall.floorHeight * float(floor);
    c.v1 = c.v0 + wall.floorHeight;
    HashStream rng = cellRandom(wall, floor, slot);
    const bool lit = rng.uniform() < kLitRoomChance;
    c.roomMaterial = wall.facadeMaterials + uint32_t(lit ? FacadeMaterial::RoomLit : FacadeMaterial::RoomDark);
    const float choice = rng.uniform();
    c.balcony = false;
    if ((wall.flags & kWallShopFront) && floor == 0 && choice < kShopWindowChance) {
        c.ou0 = c.u0 + 0.25f;
        c.ou1 = c.u1 - 0.25f;
        c.ov0 = c.v0 + 0.35f;
        c.ov1 = c.v1 - fminf(0.7f, 0.25f * wall.floorHeight);
        return c;
    }
    c.ou0 = c.u0 + 0.5f * (wall.slotWidth - wall.windowWidth);
    c.ou1 = c.ou0 + wall.windowWidth;
    c.ov1 = c.v0 + wall.sillHeight + wall.windowHeight;
    c.balcony = (wall.flags & kWallBalconies) && floor > 0 && choice < kBalconyChance;
    c.ov0 = c.v0 + (c.balcony ? 0.15f : wall.sillHeight);
    return c;
}

/// The parts of cell (floor, slot) of `wall` on `side` of its glass plane, in wall coordinates; all
/// lie within the cell's column [u0, u1] x [v0, v1] (any w), which lets the grid traversal stop at
/// the first cell hit.
template <class Out>
URBIS_HD inline void cellParts(const WallRecord& wall, const CellLayout& c, CellSide side, Out& out) {
    if (wall.style == WallStyle::Curtain) {
        addCurtainPanel(wall, c.u0, c.u1, c.v0, c.v1, c.roomMaterial, side, out);
        return;
    }
    addOpening(wall, c.u0, c.u1, c.v0, c.v1, c.ou0, c.ou1, c.ov0, c.ov1, c.roomMaterial, side, out);
    if (c.balcony) addBalcony(wall, c.u0, c.u1, c.v0, c.ou0, c.ou1, side, out);
}

/// The same, drawing the cell's layout from its hash.
template <class Out>
URBIS_HD inline void cellParts(const WallRecord& wall, uint32_t floor, uint32_t slot, CellSide side, Out& out) {
    cellParts(wall, cellLayout(wall, floor, slot), side, out);
}

} // namespace urbis
