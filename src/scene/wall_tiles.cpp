#include "scene/wall_tiles.h"

#include <cstdint>

namespace urbis {

namespace {

/// Metres by which a tile's box reaches past an edge it shares with another tile of its wall, so
/// that rounding in the box test can never lose a ray exactly on the shared edge.
constexpr float kTileOverlap = 0.01f;

/// The start of run k of n equal runs over `count` cells.
int runStart(int count, int runs, int k) { return int(int64_t(count) * k / runs); }

} // namespace

std::vector<WallRecord> splitWallsIntoTiles(const std::vector<WallRecord>& walls, WallTileSize size) {
    std::vector<WallRecord> tiles;
    tiles.reserve(walls.size());
    const int maxSlots = size.slots > 0 ? size.slots : 0xffff, maxFloors = size.floors > 0 ? size.floors : 0xffff;
    for (const WallRecord& wall : walls) {
        const int slots = wall.tileSlotEnd() - wall.slot0, floors = wall.tileFloorEnd() - wall.floor0;
        const int nu = slots > 0 ? (slots + maxSlots - 1) / maxSlots : 1;
        const int nv = floors > 0 ? (floors + maxFloors - 1) / maxFloors : 1;
        for (int b = 0; b < nv; ++b)
            for (int a = 0; a < nu; ++a) {
                WallRecord tile = wall;
                tile.slot0 = uint16_t(wall.slot0 + runStart(slots, nu, a));
                tile.slotEnd = uint16_t(wall.slot0 + runStart(slots, nu, a + 1));
                tile.floor0 = uint16_t(wall.floor0 + runStart(floors, nv, b));
                tile.floorEnd = uint16_t(wall.floor0 + runStart(floors, nv, b + 1));
                if (nu == 1) tile.slotEnd = wall.slotEnd;     // keep "to the end" (and an empty grid) as it was
                if (nv == 1) tile.floorEnd = wall.floorEnd;
                tiles.push_back(tile);
            }
    }
    return tiles;
}

Bounds3f primBounds(const WallRecord& wall) {
    const float u0 = wall.tileReachU0() - (wall.slot0 > 0 ? kTileOverlap : 0.0f);
    const float u1 = wall.tileReachU1() + (wall.tileSlotEnd() < int(wall.slots) ? kTileOverlap : 0.0f);
    const float v0 = wall.tileV0() - (wall.floor0 > 0 ? kTileOverlap : 0.0f);
    const float v1 = wall.tileV1() + (wall.tileFloorEnd() < int(wall.floors) ? kTileOverlap : 0.0f);
    Bounds3f b;
    for (int k = 0; k < 8; ++k)
        b.extend(wall.worldFromWall(k & 1 ? u1 : u0, k & 2 ? v1 : v0, k & 4 ? wall.depthFront : -wall.reachBack()));
    return b;
}

} // namespace urbis
