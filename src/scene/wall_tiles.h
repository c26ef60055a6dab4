// Walls split into tiles, each a BVH primitive of the wall kind (host).
#pragma once

#include "scene/wall_record.h"

#include <vector>

namespace urbis {

/// How walls are split into BVH primitives: tiles of at most this many slots x floors (0: no limit).
/// The default keeps whole walls: on the CPU, tiles measured slower (docs/facades.md § BVH tiles).
struct WallTileSize {
    int slots = 0, floors = 0;
};

/// `walls` split into tiles of at most `size` cells (WallRecord::slot0): each tile a copy of its
/// wall's record with a sub-range of its grid; together they give the whole wall's hits, while each
/// has a box the size of its cells, so the BVH culls what one long, deep wall box would not.
/// A wall's slots (floors) are cut into equal runs as near to each other in length as they can be.
std::vector<WallRecord> splitWallsIntoTiles(const std::vector<WallRecord>& walls, WallTileSize size);

} // namespace urbis
