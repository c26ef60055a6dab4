// The tiles of a frame that rank 0 of an MPI render hands out, one at a time, to whichever rank asks.
#pragma once

#include "film/pixel_rect.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Tiles of `tileSize` x `tileSize` pixels (smaller at the right and bottom edges) covering a
/// `width` x `height` film once, row by row from the top-left. Empty for an empty film.
std::vector<PixelRect> tilesOf(uint32_t width, uint32_t height, uint32_t tileSize);

/// The side of the tiles of an MPI render: 64 pixels (each a few TBB tasks of 16x16 on its rank), or
/// 32 or 16 where fewer than 4 tiles per rank would leave the queue too coarse to balance ranks.
uint32_t tileSizeFor(uint32_t width, uint32_t height, int ranks);

} // namespace urbis
