// The tiles of a frame that rank 0 of an MPI render hands out, one at a time, to whichever rank asks.
#pragma once

#include "film/pixel_rect.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Tiles of `tileSize` x `tileSize` pixels (smaller at the right and bottom edges) covering a
/// `width` x `height` film once, row by row from the top-left. Empty for an empty film.
std::vector<PixelRect> tilesOf(uint32_t width, uint32_t height, uint32_t tileSize);

/// The side of the tiles of a frame spread over `workers` (ranks, or devices): `largest` pixels, halved
/// (down to 16) while fewer than 4 tiles per worker would leave the queue too coarse to balance them.
/// For CPUs 64 (each tile a few TBB tasks of 16x16); for GPUs kGpuTileSide.
uint32_t tileSizeFor(uint32_t width, uint32_t height, int workers, uint32_t largest = 64);

/// The largest tile a GPU is given: 256 x 256 pixels, 512 blocks of 128 threads, enough to fill the
/// SMs of an H200 (132) several times over in one launch.
constexpr uint32_t kGpuTileSide = 256;

} // namespace urbis
