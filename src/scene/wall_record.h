// A procedural wall: one footprint edge of a building, from its minimum height to the wall top,
// split into a grid of floors x slots (host+device POD): the record of the wall kind. Everything in
// a cell (window, balcony, shop window, curtain-wall panel) is made from this record and a hash when
// a ray needs it. The tile extents below decide hits, so they use urbis.h's exact operations.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// How a wall's cells are built.
enum class WallStyle : uint8_t {
    Punched,   ///< recessed windows in a solid wall; balconies and shop windows by flags
    Curtain    ///< a glazed curtain wall: glass, mullions and spandrels over the whole grid
};

/// Optional features of a punched wall.
enum WallFlags : uint8_t {
    kWallBalconies = 1,      ///< cells above the ground floor may hold a balcony
    kWallShopFront = 2       ///< the ground floor may hold shop windows
};

/// Materials a facade uses besides the building's wall colour, at facadeMaterials + index.
enum class FacadeMaterial : uint32_t { Glass, RoomDark, RoomLit, Slab, Railing, Mullion, Spandrel, Count };

/// Wall coordinates (metres): u along the wall from its first footprint corner, v up from the wall's
/// bottom, w along the outward normal (w = 0 is the wall plane, the building's inside is w < 0).
/// world = origin + axisU * u + (0, 1, 0) * v + normal * w.
struct WallRecord {
    Vec3f origin;                ///< world position of (u, v, w) = 0: the first corner at the wall's bottom
    Vec3f axisU;                 ///< unit, horizontal, along the wall
    Vec3f normal;                ///< unit, horizontal, outward
    float width = 0, height = 0; ///< extent in u and v
    float gridU = 0, gridV = 0;  ///< lower-left corner of the cell grid (the left and bottom margins)
    float slotWidth = 0, floorHeight = 0;
    uint16_t slots = 0, floors = 0;
    float depthFront = 0;        ///< how far parts reach outward (balconies, mullions), >= 0
    float depthBack = 0;         ///< how far rooms reach inward, > 0
    float windowWidth = 0;       ///< width of a punched window
    float windowHeight = 0;      ///< height of a punched window
    float sillHeight = 0;        ///< from the cell's bottom to the window's bottom
    float reveal = 0;            ///< depth of the glass behind the wall plane
    uint32_t object = 0;         ///< the building's object id (building index + 1)
    uint32_t wallIndex = 0;      ///< which wall of the building
    uint32_t cellSeed = 0;       ///< hash2(the building's seed, wallIndex): the key of every choice per cell
    uint32_t wallMaterial = 0;   ///< the facade's own material (the building's colour)
    uint32_t facadeMaterials = 0;///< first of FacadeMaterial::Count materials
    WallStyle style = WallStyle::Punched;
    uint8_t flags = 0;           ///< WallFlags
    /// Chance, in 255ths, that a room (a shop window: shopLitChance) is lit: set at scene build by
    /// the hour and the building's use (citygen/window_schedule.h); the defaults are 30 %.
    uint8_t litChance = 77, shopLitChance = 77;
    /// The tile of the wall this record stands for, as a BVH primitive: slots [slot0, slotEnd) and
    /// floors [floor0, floorEnd) of the grid (ends clamped to slots and floors), plus the margins
    /// next to them where the tile touches the wall's edge. The defaults are the whole wall. Cell
    /// indices, hashes and geometry stay those of the whole wall, so tiles of one wall together
    /// give exactly the whole wall's hits (see splitWallIntoTiles).
    uint16_t slot0 = 0, slotEnd = 0xffff;
    uint16_t floor0 = 0, floorEnd = 0xffff;
    /// The parapet on the wall's top, around a flat roof's deck (none when parapetHeight is 0): its
    /// top at v = height from the wall plane to w = -parapetThickness, its inner face there from the
    /// deck (v = height - parapetHeight) up. The inner face runs from u = parapetInner0 to
    /// parapetInner1, where the parapets of the neighbouring walls meet it in mitres (beyond the
    /// wall's ends at reflex corners): the straight skeleton's offset of the footprint.
    float parapetHeight = 0, parapetThickness = 0;
    float parapetInner0 = 0, parapetInner1 = 0;

    /// Cost of testing one, in triangles, for the BVH's surface area heuristic: above one, so each
    /// tile gets a leaf of its own, marked costly (kWideCostlyLeaf), which the GPU tests deferred.
    /// At a cost of 1 leaves held all of a small building's walls and every ray into the leaf tested
    /// each; 4, 8 and 16 measured equal on the generated city, 16 best on San Francisco.
    static constexpr uint32_t kBvhCost = 16;

    URBIS_HD float gridWidth() const { return slotWidth * float(slots); }
    URBIS_HD float gridHeight() const { return floorHeight * float(floors); }
    /// u of the grid's right edge and v of its top (exact: they decide hits).
    URBIS_HD float gridU1() const { return slotU(slots); }
    URBIS_HD float gridV1() const { return floorV(floors); }
    /// u of slot `slot`'s left edge and v of floor `floor`'s bottom (exact).
    URBIS_HD float slotU(int slot) const { return exactMulAdd(slotWidth, float(slot), gridU); }
    URBIS_HD float floorV(int floor) const { return exactMulAdd(floorHeight, float(floor), gridV); }
    /// The tile's last slot + 1 and last floor + 1.
    URBIS_HD int tileSlotEnd() const { return slotEnd < slots ? int(slotEnd) : int(slots); }
    URBIS_HD int tileFloorEnd() const { return floorEnd < floors ? int(floorEnd) : int(floors); }
    /// The tile's extent in u and v: its cells, and the wall's margins where it touches the wall's edge.
    URBIS_HD float tileU0() const { return slot0 == 0 ? 0.0f : slotU(slot0); }
    URBIS_HD float tileU1() const { return tileSlotEnd() >= int(slots) ? width : slotU(tileSlotEnd()); }
    URBIS_HD float tileV0() const { return floor0 == 0 ? 0.0f : floorV(floor0); }
    URBIS_HD float tileV1() const { return tileFloorEnd() >= int(floors) ? height : floorV(tileFloorEnd()); }
    /// The tile's reach in u: its cells, and where it touches the wall's ends the margins and the
    /// parapet's mitres, which may reach beyond those ends (reflex corners).
    URBIS_HD float tileReachU0() const { return slot0 > 0 ? tileU0() : fminf(0.0f, parapetInner0); }
    URBIS_HD float tileReachU1() const {
        return tileSlotEnd() < int(slots) ? tileU1() : fmaxf(width, parapetInner1);
    }
    /// How far the tile's parts reach behind the wall plane: the rooms, the parapet's inner face.
    URBIS_HD float reachBack() const { return fmaxf(depthBack, parapetThickness); }
    /// World position of wall coordinates (u, v, w).
    URBIS_HD Vec3f worldFromWall(float u, float v, float w) const {
        return origin + axisU * u + Vec3f{0, v, 0} + normal * w;
    }
};

/// World bounds of a wall record's tile: its extent in u and v (WallRecord::tileU0 ...) and its
/// slab from w = -reachBack() to w = depthFront; widened where it meets another tile of its wall.
Bounds3f primBounds(const WallRecord& wall);

} // namespace urbis
