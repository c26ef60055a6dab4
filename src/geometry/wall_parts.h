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
/// The most parts a cell (or the margins) can have: a punched cell with a balcony, both sides.
inline constexpr int kMaxCellParts = 22;

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

/// Fixed-size list of parts: what marginParts and cellParts write to (the twin, tests).
struct CellParts {
    WallPart parts[kMaxCellParts];
    int count = 0;

    URBIS_HD void add(const WallPart& part) { parts[count++] = part; }
};

/// The plain margins of a wall around its cell grid, as quads in the plane w = 0 (left, right,
/// bottom, top; empty ones left out).
URBIS_HD inline void marginParts(const WallRecord& wall, CellParts& out) {
    const float u0 = wall.gridU, u1 = wall.gridU + wall.gridWidth();
    const float v0 = wall.gridV, v1 = wall.gridV + wall.gridHeight();
    const uint32_t m = wall.wallMaterial;
    if (u0 > 0.0f) out.add({{0, 0, 0}, {u0, wall.height, 0}, 2, SurfacePart::Facade, m});
    if (u1 < wall.width) out.add({{u1, 0, 0}, {wall.width, wall.height, 0}, 2, SurfacePart::Facade, m});
    if (v0 > 0.0f) out.add({{u0, 0, 0}, {u1, v0, 0}, 2, SurfacePart::Facade, m});
    if (v1 < wall.height) out.add({{u0, v1, 0}, {u1, wall.height, 0}, 2, SurfacePart::Facade, m});
}

/// The hash that every choice of one cell draws from.
URBIS_HD inline HashStream cellRandom(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    return HashStream{hash3(hash2(wall.seed, wall.wallIndex), floor, slot)};
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

// A cell's parts one at a time, by index, so that the intersector tests them in one loop: lanes of
// a GPU warp at different parts of different cells still run the one part test together (a list
// written part by part from some 30 places ran it at each place with a few lanes; docs/gpu_notes.md).
// Punched cells number their parts: 0-3 the frame around the opening in the wall plane, 4-7 its
// jambs, 8 the glass, 9-12 the room's front wall (the frame in the glass plane), 13-17 the room,
// 18-21 the balcony (slab, front and side railings). Curtain-wall cells: 0-3 the half mullions on
// the cell's edges, 4 the spandrel, 5 the glass, 6-10 the room.

/// The room behind an opening: part q (0 back, 1 and 2 sides, 3 floor, 4 ceiling) of five quads
/// inset from the cell by a thin inner wall, from w = -depthBack to w = front.
URBIS_HD inline WallPart roomPart(const WallRecord& wall, const CellLayout& c, float front, int q) {
    constexpr float kInset = 0.05f;
    const float a = c.u0 + kInset, b = c.u1 - kInset, lo = c.v0 + kInset, hi = c.v1 - kInset, back = -wall.depthBack;
    const uint32_t m = c.roomMaterial;
    switch (q) {
    case 0: return {{a, lo, back}, {b, hi, back}, 2, SurfacePart::Room, m};
    case 1: return {{a, lo, back}, {a, hi, front}, 0, SurfacePart::Room, m};
    case 2: return {{b, lo, back}, {b, hi, front}, 0, SurfacePart::Room, m};
    case 3: return {{a, lo, back}, {b, lo, front}, 1, SurfacePart::Room, m};
    default: return {{a, hi, back}, {b, hi, front}, 1, SurfacePart::Room, m};
    }
}

/// Part q of the four quads of the plane w around the cell's opening.
URBIS_HD inline WallPart framePart(const CellLayout& c, float w, SurfacePart part, uint32_t material, int q) {
    switch (q) {
    case 0: return {{c.u0, c.v0, w}, {c.ou0, c.v1, w}, 2, part, material};
    case 1: return {{c.ou1, c.v0, w}, {c.u1, c.v1, w}, 2, part, material};
    case 2: return {{c.ou0, c.v0, w}, {c.ou1, c.ov0, w}, 2, part, material};
    default: return {{c.ou0, c.ov1, w}, {c.ou1, c.v1, w}, 2, part, material};
    }
}

/// Part q of the opening's four jambs, from the wall plane back to the glass.
URBIS_HD inline WallPart jambPart(const WallRecord& wall, const CellLayout& c, int q) {
    const float r = -wall.reveal;
    const uint32_t m = wall.wallMaterial;
    switch (q) {
    case 0: return {{c.ou0, c.ov0, r}, {c.ou0, c.ov1, 0}, 0, SurfacePart::Jamb, m};
    case 1: return {{c.ou1, c.ov0, r}, {c.ou1, c.ov1, 0}, 0, SurfacePart::Jamb, m};
    case 2: return {{c.ou0, c.ov0, r}, {c.ou1, c.ov0, 0}, 1, SurfacePart::Jamb, m};
    default: return {{c.ou0, c.ov1, r}, {c.ou1, c.ov1, 0}, 1, SurfacePart::Jamb, m};
    }
}

/// Part q of a balcony in front of the opening: a slab on the cell's floor and a railing (front and
/// two sides) around it, depthFront metres deep.
URBIS_HD inline WallPart balconyPart(const WallRecord& wall, const CellLayout& c, int q) {
    constexpr float kSlab = 0.15f, kRail = 0.05f, kRailHeight = 1.0f;
    const float a = fmaxf(c.u0 + 0.1f, c.ou0 - 0.6f), b = fminf(c.u1 - 0.1f, c.ou1 + 0.6f), f = wall.depthFront;
    const uint32_t rail = wall.facadeMaterials + uint32_t(FacadeMaterial::Railing);
    const float top = c.v0 + kSlab, railTop = top + kRailHeight;
    switch (q) {
    case 0: return {{a, c.v0, 0}, {b, top, f}, kWallPartBox, SurfacePart::BalconySlab,
                    wall.facadeMaterials + uint32_t(FacadeMaterial::Slab)};
    case 1: return {{a, top, f - kRail}, {b, railTop, f}, kWallPartBox, SurfacePart::Railing, rail};
    case 2: return {{a, top, 0}, {a + kRail, railTop, f - kRail}, kWallPartBox, SurfacePart::Railing, rail};
    default: return {{b - kRail, top, 0}, {b, railTop, f - kRail}, kWallPartBox, SurfacePart::Railing, rail};
    }
}

/// Part q (numbered as above) of a curtain-wall panel filling the cell: half mullions on its four
/// edges, a spandrel below wall.sillHeight and glass above it, both `reveal` deep, and the room.
URBIS_HD inline WallPart curtainPart(const WallRecord& wall, const CellLayout& c, int q) {
    constexpr float kHalfMullion = 0.06f, kMullionDepth = 0.12f;
    const float r = -wall.reveal, m = kHalfMullion, split = c.v0 + wall.sillHeight;
    const uint32_t mullion = wall.facadeMaterials + uint32_t(FacadeMaterial::Mullion);
    switch (q) {
    case 0: return {{c.u0, c.v0, r}, {c.u0 + m, c.v1, kMullionDepth}, kWallPartBox, SurfacePart::Mullion, mullion};
    case 1: return {{c.u1 - m, c.v0, r}, {c.u1, c.v1, kMullionDepth}, kWallPartBox, SurfacePart::Mullion, mullion};
    case 2: return {{c.u0 + m, c.v0, r}, {c.u1 - m, c.v0 + m, kMullionDepth}, kWallPartBox, SurfacePart::Mullion, mullion};
    case 3: return {{c.u0 + m, c.v1 - m, r}, {c.u1 - m, c.v1, kMullionDepth}, kWallPartBox, SurfacePart::Mullion, mullion};
    case 4: return {{c.u0 + m, c.v0 + m, r}, {c.u1 - m, split, r}, 2, SurfacePart::Spandrel,
                    wall.facadeMaterials + uint32_t(FacadeMaterial::Spandrel)};
    case 5: return {{c.u0 + m, split, r}, {c.u1 - m, c.v1 - m, r}, 2, SurfacePart::Glass,
                    wall.facadeMaterials + uint32_t(FacadeMaterial::Glass)};
    default: return roomPart(wall, c, r, q - 6);
    }
}

/// Part q (numbered as above) of a punched cell.
URBIS_HD inline WallPart punchedPart(const WallRecord& wall, const CellLayout& c, int q) {
    const float r = -wall.reveal;
    if (q < 4) return framePart(c, 0.0f, SurfacePart::Facade, wall.wallMaterial, q);
    if (q < 8) return jambPart(wall, c, q - 4);
    if (q == 8)
        return {{c.ou0, c.ov0, r}, {c.ou1, c.ov1, r}, 2, SurfacePart::Glass,
                wall.facadeMaterials + uint32_t(FacadeMaterial::Glass)};
    if (q < 13) return framePart(c, r, SurfacePart::Room, c.roomMaterial, q - 9);
    if (q < 18) return roomPart(wall, c, r, q - 13);
    return balconyPart(wall, c, q - 18);
}

/// How many parts of the cell lie on `side` of its glass plane (all lie within the cell's column
/// [u0, u1] x [v0, v1], any w, which lets the grid traversal stop at the first cell hit): the glass
/// itself on both sides, in front of it the frame, jambs, balcony and mullions, behind it the room.
URBIS_HD inline int cellPartCount(const WallRecord& wall, const CellLayout& c, CellSide side) {
    if (wall.style == WallStyle::Curtain) return side == CellSide::Front ? 6 : 11;
    const int balcony = c.balcony && side != CellSide::Back ? 4 : 0;
    return (side == CellSide::Front ? 9 : (side == CellSide::Back ? 10 : 18)) + balcony;
}

/// Part k < cellPartCount of the cell on `side`: the numbering above without the other side's parts.
URBIS_HD inline WallPart cellPart(const WallRecord& wall, const CellLayout& c, CellSide side, int k) {
    if (wall.style == WallStyle::Curtain) return curtainPart(wall, c, k);
    if (side == CellSide::Back) return punchedPart(wall, c, k + 8);
    return punchedPart(wall, c, side == CellSide::Front && k >= 9 ? k + 9 : k);
}

/// Every part of cell (floor, slot) of `wall` on `side`, drawing its layout from its hash.
URBIS_HD inline void cellParts(const WallRecord& wall, uint32_t floor, uint32_t slot, CellSide side, CellParts& out) {
    const CellLayout c = cellLayout(wall, floor, slot);
    const int n = cellPartCount(wall, c, side);
    for (int k = 0; k < n; ++k) out.add(cellPart(wall, c, side, k));
}

} // namespace urbis
