// The parts of one cell of a procedural wall, made on demand from the wall record and a hash of
// (building, wall, floor, slot): nothing per window is stored. Host+device; the procedural
// intersector and the triangle twin both call these, so the two representations agree.
#pragma once

#include "scene/wall_record.h"
#include "math/hash.h"
#include "scene/surface_part.h"

namespace urbis {

/// What a part facing w (a quad in the wall or glass plane, a box's faces across w) holds where the
/// cell's opening is: a window's, or a curtain-wall panel between its mullions.
enum class PartOpening : uint8_t {
    None,    ///< nothing: the part is whole
    Hole,    ///< a hole: the frame around a window in the wall plane, a curtain cell's mullions
    Glass,   ///< the panel: the glass plane with the room's front wall (or the mullions) around it
    Recess   ///< a box that is the opening's recess, open at its front: a ray meets the face it
             ///< leaves through, a side (jamb, mullion) or the back (the panel)
};

/// An axis-aligned quad or box in wall coordinates (metres). A quad has lo[axis] == hi[axis]; one
/// facing w (the wall or the glass plane) or a box may have the cell's opening (u
/// openingLo.x..openingHi.x, v openingLo.y..openingHi.y).
struct WallPart {
    Vec3f lo, hi;
    uint8_t axis = 0;        ///< a quad's normal axis (0: u, 1: v, 2: w), or kWallPartBox
    SurfacePart part = SurfacePart::Facade;
    uint32_t material = 0;
    PartOpening opening = PartOpening::None;
    Vec2f openingLo{}, openingHi{};
    /// The panel in the opening (PartOpening::Glass, Recess): glass (openingMaterial), a curtain
    /// cell's spandrel below v = panelSplit (the material FacadeMaterial::Spandrel is to Glass).
    uint32_t openingMaterial = 0;
    float panelSplit = 0;
};

/// WallPart::axis of a quad facing u, v or w (its normal axis), and of a box.
inline constexpr uint8_t kFacingU = 0, kFacingV = 1, kFacingW = 2, kWallPartBox = 3;
/// The most parts a cell (or the margins) can have: a punched cell with a balcony, both sides.
inline constexpr int kMaxCellParts = 22;

/// Chance that a cell of a wall with balconies holds one (above the ground floor).
inline constexpr float kBalconyChance = 0.5f;
/// Chance that a ground-floor cell of a shop-front wall holds a shop window (as in the thesis).
inline constexpr float kShopWindowChance = 0.8f;
/// Half a curtain wall's mullion (the frame of each of its cells) and how far mullions reach out
/// from the wall plane, metres.
inline constexpr float kHalfMullion = 0.06f, kMullionDepth = 0.12f;
/// A shop window's margins in its cell (metres): at either side, below it, and above it (at most
/// kShopWindowTopShare of the floor's height).
inline constexpr float kShopWindowSide = 0.25f, kShopWindowBottom = 0.35f, kShopWindowTop = 0.7f,
                       kShopWindowTopShare = 0.25f;
/// The room's inset from its cell (a thin inner wall), metres.
inline constexpr float kRoomInset = 0.05f;
/// A balcony (metres): its slab's thickness (a balcony door's sill stands on it), the railing's
/// thickness and height above the slab, how far the slab reaches past the opening at either side and
/// how near it comes to the cell's edge.
inline constexpr float kBalconySlab = 0.15f, kRailingThickness = 0.05f, kRailingHeight = 1.0f, kBalconyReach = 0.6f,
                       kBalconyEdgeGap = 0.1f;

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
    const float u0 = wall.gridU, u1 = wall.gridU1();
    const float v0 = wall.gridV, v1 = wall.gridV1();
    const uint32_t m = wall.wallMaterial;
    if (u0 > 0.0f) out.add({{0, 0, 0}, {u0, wall.height, 0}, kFacingW, SurfacePart::Facade, m});
    if (u1 < wall.width) out.add({{u1, 0, 0}, {wall.width, wall.height, 0}, kFacingW, SurfacePart::Facade, m});
    if (v0 > 0.0f) out.add({{u0, 0, 0}, {u1, v0, 0}, kFacingW, SurfacePart::Facade, m});
    if (v1 < wall.height) out.add({{u0, v1, 0}, {u1, wall.height, 0}, kFacingW, SurfacePart::Facade, m});
}

/// The hash that every choice of one cell draws from.
URBIS_HD inline HashStream cellRandom(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    return HashStream{hash3(wall.cellSeed, floor, slot)};
}

/// What a cell holds, drawn from its hash: the cell's extent, its opening (window, balcony door or
/// shop window; a curtain cell's panel between its mullions) and the room's material.
struct CellLayout {
    float u0, u1, v0, v1;        ///< the cell
    float ou0, ou1, ov0, ov1;    ///< the opening
    uint32_t roomMaterial;
    bool balcony;
};

/// A cell's first two draws, whatever the cell: whether its room is lit (against the chance of a
/// shop window or of a room, which the hour and the building's use set: citygen/window_schedule.h),
/// and its opening (`choice`). The lit-window light sampler asks only this (lights/window_light.h).
struct CellDraws {
    bool lit, shopWindow;
    float choice;
};

URBIS_HD inline CellDraws cellDraws(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    HashStream rng = cellRandom(wall, floor, slot);
    const float litDraw = rng.uniform(), choice = rng.uniform();
    const bool shopWindow = wall.style == WallStyle::Punched && (wall.flags & kWallShopFront) && floor == 0 &&
                            choice < kShopWindowChance;
    const float chance = float(shopWindow ? wall.shopLitChance : wall.litChance) * (1.0f / 255.0f);
    return {litDraw < chance, shopWindow, choice};
}

/// The layout of cell (floor, slot) of `wall`; exact arithmetic (urbis.h): it decides hits.
URBIS_HD inline CellLayout cellLayout(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    CellLayout c;
    c.u0 = wall.slotU(int(slot));
    c.u1 = c.u0 + wall.slotWidth;
    c.v0 = wall.floorV(int(floor));
    c.v1 = c.v0 + wall.floorHeight;
    const CellDraws draws = cellDraws(wall, floor, slot);
    const bool shopWindow = draws.shopWindow;
    const float choice = draws.choice;
    c.roomMaterial = wall.facadeMaterials + uint32_t(draws.lit ? FacadeMaterial::RoomLit : FacadeMaterial::RoomDark);
    c.balcony = false;
    if (wall.style == WallStyle::Curtain) {
        c.ou0 = c.u0 + kHalfMullion, c.ou1 = c.u1 - kHalfMullion;
        c.ov0 = c.v0 + kHalfMullion, c.ov1 = c.v1 - kHalfMullion;
        return c;
    }
    if (shopWindow) {
        c.ou0 = c.u0 + kShopWindowSide;
        c.ou1 = c.u1 - kShopWindowSide;
        c.ov0 = c.v0 + kShopWindowBottom;
        c.ov1 = c.v1 - fminf(kShopWindowTop, exactMul(kShopWindowTopShare, wall.floorHeight));
        return c;
    }
    c.ou0 = exactMulAdd(0.5f, wall.slotWidth - wall.windowWidth, c.u0);
    c.ou1 = c.ou0 + wall.windowWidth;
    c.ov1 = c.v0 + wall.sillHeight + wall.windowHeight;
    c.balcony = (wall.flags & kWallBalconies) && floor > 0 && choice < kBalconyChance;
    c.ov0 = c.v0 + (c.balcony ? kBalconySlab : wall.sillHeight);
    return c;
}

// A cell's parts one at a time, by index, so that the intersector tests them in one loop: lanes of
// a GPU warp at different parts of different cells still run the one part test together (a list
// written part by part from some 30 places ran it at each place with a few lanes).
// Each part is a recipe: which of the cell's coordinates (CellCoords) its corners take, its axis,
// SurfacePart and material. One short piece of code builds every part from its recipe; a function
// per part kind made the wall code too large for the GPU's instruction cache.
// The recipes (PartRecipeId) from FrameLeft to RailingRight make a punched cell as the triangle twin
// stores it; those from MullionLeft to CurtainGlass a curtain-wall cell's own parts (its room is the
// punched cell's). The intersector tests fewer, larger parts of the same surfaces (kPartLists), those
// from FrameWithHole on: the frame as one quad with the opening as its hole, the glass plane as one
// quad with the glass in its opening, the room as one box seen from inside, the window's recess as one
// box (its jambs and glass); a curtain cell's mullions as one box with the panel as its hole, the
// recess between them (mullions and panel) and its glass plane as one quad, the panel in its opening.

/// The coordinates (wall space, metres) that a cell's parts are made of: u, then v, then w values.
enum CellCoord : uint8_t {
    U0, U1, OpeningU0, OpeningU1, RoomU0, RoomU1, BalconyU0, BalconyU1, RailU0, RailU1,
    V0, V1, OpeningV0, OpeningV1, RoomV0, RoomV1, SlabTop, RailTop, PanelSplit,
    WallPlane, GlassPlane, RoomBack, BalconyFront, RailBack, MullionFront,
    kCellCoordCount
};

/// The values of every CellCoord of one cell.
struct CellCoords {
    float at[kCellCoordCount];
};

/// A cell's coordinates: its edges, its opening's, the room inset from the cell by a thin inner
/// wall, a balcony's slab and railing around the opening, and the split between a curtain panel's
/// spandrel and glass (a punched cell's opening is glass from the cell's bottom up).
URBIS_HD inline CellCoords cellCoords(const WallRecord& wall, const CellLayout& c) {
    CellCoords k;
    float* at = k.at;
    at[U0] = c.u0, at[U1] = c.u1, at[OpeningU0] = c.ou0, at[OpeningU1] = c.ou1;
    at[RoomU0] = c.u0 + kRoomInset, at[RoomU1] = c.u1 - kRoomInset;
    at[BalconyU0] = fmaxf(c.u0 + kBalconyEdgeGap, c.ou0 - kBalconyReach);
    at[BalconyU1] = fminf(c.u1 - kBalconyEdgeGap, c.ou1 + kBalconyReach);
    at[RailU0] = at[BalconyU0] + kRailingThickness, at[RailU1] = at[BalconyU1] - kRailingThickness;
    at[V0] = c.v0, at[V1] = c.v1, at[OpeningV0] = c.ov0, at[OpeningV1] = c.ov1;
    at[RoomV0] = c.v0 + kRoomInset, at[RoomV1] = c.v1 - kRoomInset;
    at[SlabTop] = c.v0 + kBalconySlab, at[RailTop] = at[SlabTop] + kRailingHeight;
    at[PanelSplit] = wall.style == WallStyle::Curtain ? c.v0 + wall.sillHeight : c.v0;
    at[WallPlane] = 0.0f, at[GlassPlane] = -wall.reveal, at[RoomBack] = -wall.depthBack;
    at[BalconyFront] = wall.depthFront, at[RailBack] = wall.depthFront - kRailingThickness;
    at[MullionFront] = kMullionDepth;
    return k;
}

/// A part as 42 bits: six CellCoords (kCoordBits each: lo u v w, hi u v w), the axis (2 bits: a
/// quad's normal, or kWallPartBox), the SurfacePart (4 bits), the material (4 bits: 0 the wall's, 1
/// the room's, 2 + n FacadeMaterial n) and the PartOpening (2 bits) of a quad with the cell's opening.
using PartRecipe = uint64_t;

/// Where each field of a PartRecipe lies: corner coordinate i (lo u, v, w, then hi u, v, w) at bit
/// i kCoordBits, then the axis, the SurfacePart, the material and the PartOpening; and their masks.
inline constexpr int kCoordBits = 5, kAxisShift = 30, kPartShift = 32, kMaterialShift = 36, kOpeningShift = 40;
inline constexpr uint32_t kCoordMask = 31u, kAxisMask = 3u, kPartMask = 15u, kMaterialMask = 15u, kOpeningMask = 3u;
static_assert(6 * kCoordBits <= kAxisShift && kCellCoordCount <= (1 << kCoordBits), "a CellCoord fits its field");

/// A part's two corners, each as the CellCoords of its u, v and w.
struct PartCorner {
    CellCoord u, v, w;
};

URBIS_HD constexpr PartRecipe partRecipe(PartCorner lo, PartCorner hi, uint8_t axis, SurfacePart part,
                                         uint32_t material, PartOpening opening = PartOpening::None) {
    const CellCoord corners[6] = {lo.u, lo.v, lo.w, hi.u, hi.v, hi.w};
    PartRecipe recipe = 0;
    for (int i = 0; i < 6; ++i) recipe |= PartRecipe(corners[i]) << (i * kCoordBits);
    return recipe | PartRecipe(axis) << kAxisShift | PartRecipe(part) << kPartShift |
           PartRecipe(material) << kMaterialShift | PartRecipe(opening) << kOpeningShift;
}
inline constexpr uint32_t kWallMaterialCode = 0, kRoomMaterialCode = 1;
URBIS_HD constexpr uint32_t facadeMaterialCode(FacadeMaterial m) { return 2 + uint32_t(m); }

/// The recipes, by name: kPartRecipes' rows in this order. Of a punched cell: the frame round the
/// opening in the wall plane (left, right, below, above), its jambs (left, right, the sill, the
/// head), the glass, the room's front wall (the frame in the glass plane), the room (back, sides,
/// floor, ceiling), the balcony (slab, front and side railings); of a curtain-wall cell: its half
/// mullions, the spandrel and the glass; then the intersector's larger parts.
enum PartRecipeId : uint8_t {
    FrameLeft, FrameRight, FrameBelow, FrameAbove,
    JambLeft, JambRight, JambSill, JambHead,
    WindowGlass,
    FrontWallLeft, FrontWallRight, FrontWallBelow, FrontWallAbove,
    RoomBackWall, RoomLeftWall, RoomRightWall, RoomFloor, RoomCeiling,
    BalconySlab, RailingFront, RailingLeft, RailingRight,
    MullionLeft, MullionRight, MullionBelow, MullionAbove,
    CurtainSpandrel, CurtainGlass,
    FrameWithHole, PunchedGlassPlane, RoomBox, WindowRecess,
    MullionsWithHole, CurtainRecess, CurtainGlassPlane,
    kPartRecipeCount
};

/// Every part's recipe, in PartRecipeId order; a curtain-wall cell's parts are half mullions
/// reaching from the glass plane out to MullionFront, a spandrel below the panel split and glass above
/// it. A table, not a switch, so that lanes of a GPU warp at different parts load their recipes
/// together instead of taking turns.
URBIS_TABLE PartRecipe kPartRecipes[] = {
    // FrameLeft, FrameRight, FrameBelow, FrameAbove
    partRecipe({U0, V0, WallPlane}, {OpeningU0, V1, WallPlane}, kFacingW, SurfacePart::Facade, kWallMaterialCode),
    partRecipe({OpeningU1, V0, WallPlane}, {U1, V1, WallPlane}, kFacingW, SurfacePart::Facade, kWallMaterialCode),
    partRecipe({OpeningU0, V0, WallPlane}, {OpeningU1, OpeningV0, WallPlane}, kFacingW, SurfacePart::Facade,
               kWallMaterialCode),
    partRecipe({OpeningU0, OpeningV1, WallPlane}, {OpeningU1, V1, WallPlane}, kFacingW, SurfacePart::Facade,
               kWallMaterialCode),
    // JambLeft, JambRight, JambSill, JambHead
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU0, OpeningV1, WallPlane}, kFacingU, SurfacePart::Jamb,
               kWallMaterialCode),
    partRecipe({OpeningU1, OpeningV0, GlassPlane}, {OpeningU1, OpeningV1, WallPlane}, kFacingU, SurfacePart::Jamb,
               kWallMaterialCode),
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU1, OpeningV0, WallPlane}, kFacingV, SurfacePart::Jamb,
               kWallMaterialCode),
    partRecipe({OpeningU0, OpeningV1, GlassPlane}, {OpeningU1, OpeningV1, WallPlane}, kFacingV, SurfacePart::Jamb,
               kWallMaterialCode),
    // WindowGlass
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU1, OpeningV1, GlassPlane}, kFacingW, SurfacePart::Glass,
               facadeMaterialCode(FacadeMaterial::Glass)),
    // FrontWallLeft, FrontWallRight, FrontWallBelow, FrontWallAbove
    partRecipe({U0, V0, GlassPlane}, {OpeningU0, V1, GlassPlane}, kFacingW, SurfacePart::Room, kRoomMaterialCode),
    partRecipe({OpeningU1, V0, GlassPlane}, {U1, V1, GlassPlane}, kFacingW, SurfacePart::Room, kRoomMaterialCode),
    partRecipe({OpeningU0, V0, GlassPlane}, {OpeningU1, OpeningV0, GlassPlane}, kFacingW, SurfacePart::Room,
               kRoomMaterialCode),
    partRecipe({OpeningU0, OpeningV1, GlassPlane}, {OpeningU1, V1, GlassPlane}, kFacingW, SurfacePart::Room,
               kRoomMaterialCode),
    // RoomBackWall, RoomLeftWall, RoomRightWall, RoomFloor, RoomCeiling
    partRecipe({RoomU0, RoomV0, RoomBack}, {RoomU1, RoomV1, RoomBack}, kFacingW, SurfacePart::Room, kRoomMaterialCode),
    partRecipe({RoomU0, RoomV0, RoomBack}, {RoomU0, RoomV1, GlassPlane}, kFacingU,
               SurfacePart::Room, kRoomMaterialCode),
    partRecipe({RoomU1, RoomV0, RoomBack}, {RoomU1, RoomV1, GlassPlane}, kFacingU,
               SurfacePart::Room, kRoomMaterialCode),
    partRecipe({RoomU0, RoomV0, RoomBack}, {RoomU1, RoomV0, GlassPlane}, kFacingV,
               SurfacePart::Room, kRoomMaterialCode),
    partRecipe({RoomU0, RoomV1, RoomBack}, {RoomU1, RoomV1, GlassPlane}, kFacingV,
               SurfacePart::Room, kRoomMaterialCode),
    // BalconySlab, RailingFront, RailingLeft, RailingRight
    partRecipe({BalconyU0, V0, WallPlane}, {BalconyU1, SlabTop, BalconyFront}, kWallPartBox, SurfacePart::BalconySlab,
               facadeMaterialCode(FacadeMaterial::Slab)),
    partRecipe({BalconyU0, SlabTop, RailBack}, {BalconyU1, RailTop, BalconyFront}, kWallPartBox, SurfacePart::Railing,
               facadeMaterialCode(FacadeMaterial::Railing)),
    partRecipe({BalconyU0, SlabTop, WallPlane}, {RailU0, RailTop, RailBack}, kWallPartBox, SurfacePart::Railing,
               facadeMaterialCode(FacadeMaterial::Railing)),
    partRecipe({RailU1, SlabTop, WallPlane}, {BalconyU1, RailTop, RailBack}, kWallPartBox, SurfacePart::Railing,
               facadeMaterialCode(FacadeMaterial::Railing)),
    // MullionLeft, MullionRight, MullionBelow, MullionAbove
    partRecipe({U0, V0, GlassPlane}, {OpeningU0, V1, MullionFront}, kWallPartBox, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion)),
    partRecipe({OpeningU1, V0, GlassPlane}, {U1, V1, MullionFront}, kWallPartBox, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion)),
    partRecipe({OpeningU0, V0, GlassPlane}, {OpeningU1, OpeningV0, MullionFront}, kWallPartBox, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion)),
    partRecipe({OpeningU0, OpeningV1, GlassPlane}, {OpeningU1, V1, MullionFront}, kWallPartBox, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion)),
    // CurtainSpandrel, CurtainGlass
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU1, PanelSplit, GlassPlane}, kFacingW,
               SurfacePart::Spandrel, facadeMaterialCode(FacadeMaterial::Spandrel)),
    partRecipe({OpeningU0, PanelSplit, GlassPlane}, {OpeningU1, OpeningV1, GlassPlane}, kFacingW, SurfacePart::Glass,
               facadeMaterialCode(FacadeMaterial::Glass)),
    // FrameWithHole, PunchedGlassPlane, RoomBox, WindowRecess
    partRecipe({U0, V0, WallPlane}, {U1, V1, WallPlane}, kFacingW, SurfacePart::Facade, kWallMaterialCode,
               PartOpening::Hole),
    partRecipe({U0, V0, GlassPlane}, {U1, V1, GlassPlane}, kFacingW, SurfacePart::Room, kRoomMaterialCode,
               PartOpening::Glass),
    partRecipe({RoomU0, RoomV0, RoomBack}, {RoomU1, RoomV1, GlassPlane}, kWallPartBox, SurfacePart::Room,
               kRoomMaterialCode),
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU1, OpeningV1, WallPlane}, kWallPartBox, SurfacePart::Jamb,
               kWallMaterialCode, PartOpening::Recess),
    // MullionsWithHole, CurtainRecess, CurtainGlassPlane
    partRecipe({U0, V0, GlassPlane}, {U1, V1, MullionFront}, kWallPartBox, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion), PartOpening::Hole),
    partRecipe({OpeningU0, OpeningV0, GlassPlane}, {OpeningU1, OpeningV1, MullionFront}, kWallPartBox,
               SurfacePart::Mullion, facadeMaterialCode(FacadeMaterial::Mullion), PartOpening::Recess),
    partRecipe({U0, V0, GlassPlane}, {U1, V1, GlassPlane}, kFacingW, SurfacePart::Mullion,
               facadeMaterialCode(FacadeMaterial::Mullion), PartOpening::Glass),
};
static_assert(sizeof(kPartRecipes) / sizeof(kPartRecipes[0]) == kPartRecipeCount, "a recipe per PartRecipeId");

/// The recipes of each list of parts that cellPart walks, by wall style and CellSide: a punched
/// cell's front (the frame with its hole, the recess; then a balcony's four boxes), its back (the
/// glass plane, the room) and both sides as the twin stores them; a curtain-wall cell's front (the
/// mullions with their hole, the recess), back (the glass plane, the room) and both sides as the
/// twin stores them.
URBIS_TABLE uint8_t kPartLists[] = {
    // punched, front
    FrameWithHole, WindowRecess, BalconySlab, RailingFront, RailingLeft, RailingRight,
    // punched, back
    PunchedGlassPlane, RoomBox,
    // punched, both
    FrameLeft, FrameRight, FrameBelow, FrameAbove, JambLeft, JambRight, JambSill, JambHead, WindowGlass,
    FrontWallLeft, FrontWallRight, FrontWallBelow, FrontWallAbove, RoomBackWall, RoomLeftWall, RoomRightWall, RoomFloor,
    RoomCeiling, BalconySlab, RailingFront, RailingLeft, RailingRight,
    // curtain, front
    MullionsWithHole, CurtainRecess,
    // curtain, back
    CurtainGlassPlane, RoomBox,
    // curtain, both
    MullionLeft, MullionRight, MullionBelow, MullionAbove, CurtainSpandrel, CurtainGlass, RoomBackWall, RoomLeftWall,
    RoomRightWall, RoomFloor, RoomCeiling,
};

/// The lengths of kPartLists' lists (a balcony adds kBalconyParts to a punched cell's front and
/// both sides) and where each starts: every cell is two parts on either side of its glass plane.
inline constexpr int kSideParts = 2, kPunchedBothParts = 18, kBalconyParts = 4, kCurtainBothParts = 11;
inline constexpr int kPunchedFrontList = 0, kPunchedBackList = kPunchedFrontList + kSideParts + kBalconyParts;
inline constexpr int kPunchedBothList = kPunchedBackList + kSideParts;
inline constexpr int kCurtainFrontList = kPunchedBothList + kPunchedBothParts + kBalconyParts;
inline constexpr int kCurtainBackList = kCurtainFrontList + kSideParts;
inline constexpr int kCurtainBothList = kCurtainBackList + kSideParts;
static_assert(sizeof(kPartLists) == kCurtainBothList + kCurtainBothParts, "kPartLists' lists and their lengths");
static_assert(kMaxCellParts == kPunchedBothParts + kBalconyParts, "the longest list is a punched cell's, both sides");

/// The part that `recipe` makes of a cell with coordinates `k`.
URBIS_HD inline WallPart partFromRecipe(const WallRecord& wall, const CellLayout& c, const CellCoords& k,
                                       PartRecipe recipe) {
    const auto coord = [&](int corner) { return k.at[(recipe >> (corner * kCoordBits)) & kCoordMask]; };
    const uint32_t material = uint32_t(recipe >> kMaterialShift) & kMaterialMask;
    WallPart p;
    p.lo = {coord(0), coord(1), coord(2)};
    p.hi = {coord(3), coord(4), coord(5)};
    p.axis = uint8_t((recipe >> kAxisShift) & kAxisMask);
    p.part = SurfacePart((recipe >> kPartShift) & kPartMask);
    p.opening = PartOpening((recipe >> kOpeningShift) & kOpeningMask);
    if (p.opening != PartOpening::None) {
        p.openingLo = {k.at[OpeningU0], k.at[OpeningV0]};
        p.openingHi = {k.at[OpeningU1], k.at[OpeningV1]};
        p.openingMaterial = wall.facadeMaterials + uint32_t(FacadeMaterial::Glass);
        p.panelSplit = k.at[PanelSplit];
    }
    const uint32_t facade = wall.facadeMaterials + (material - facadeMaterialCode(FacadeMaterial(0)));
    p.material = material == kWallMaterialCode ? wall.wallMaterial : (material == kRoomMaterialCode ? c.roomMaterial : facade);
    return p;
}

/// How many parts of the cell lie on `side` of its glass plane (all lie within the cell's column
/// [u0, u1] x [v0, v1], any w, which lets the grid traversal stop at the first cell hit): the glass
/// plane on both sides, in front of it the frame, jambs, balcony and mullions, behind it the room.
URBIS_HD inline int cellPartCount(const WallRecord& wall, const CellLayout& c, CellSide side) {
    const bool front = side == CellSide::Front, back = side == CellSide::Back;
    if (wall.style == WallStyle::Curtain) return front || back ? kSideParts : kCurtainBothParts;
    const int balcony = c.balcony && !back ? kBalconyParts : 0;
    return (front || back ? kSideParts : kPunchedBothParts) + balcony;
}

/// Part k < cellPartCount of the cell on `side` (coordinates k from cellCoords), from kPartLists.
URBIS_HD inline WallPart cellPart(const WallRecord& wall, const CellLayout& c, const CellCoords& coords, CellSide side,
                                  int k) {
    const bool curtain = wall.style == WallStyle::Curtain;
    int list;
    if (side == CellSide::Front) list = curtain ? kCurtainFrontList : kPunchedFrontList;
    else if (side == CellSide::Back) list = curtain ? kCurtainBackList : kPunchedBackList;
    else list = curtain ? kCurtainBothList : kPunchedBothList;
    return partFromRecipe(wall, c, coords, kPartRecipes[kPartLists[list + k]]);
}

/// Every part of cell (floor, slot) of `wall` on `side`, drawing its layout from its hash.
URBIS_HD inline void cellParts(const WallRecord& wall, uint32_t floor, uint32_t slot, CellSide side, CellParts& out) {
    const CellLayout c = cellLayout(wall, floor, slot);
    const CellCoords coords = cellCoords(wall, c);
    const int n = cellPartCount(wall, c, side);
    for (int k = 0; k < n; ++k) out.add(cellPart(wall, c, coords, side, k));
}

} // namespace urbis
