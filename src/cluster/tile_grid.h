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

/// The largest tile a GPU rank of an MPI render is given: 256 x 256 pixels, 512 blocks of 128 threads,
/// about one wave on an H200 (132 SMs, four blocks each). The rank renders one at a time (docs/scale.md);
/// the devices of one process take bands on several streams instead (bandsOf).
constexpr uint32_t kGpuTileSide = 256;

/// The CUDA streams, each with its host thread, that render one GPU's tiles at once (GpuTileStream):
/// on an H200, SF at 1080p, 64 spp, in tiles of 256 took 1.81, 1.12, 0.94, 0.88 s on 1 to 4 streams,
/// against 0.79 s in one launch (BENCHMARKS.md § Several GPUs).
constexpr int kGpuStreamsPerDevice = 4;

/// The tiles of a frame spread over `streams` GPU streams in all (of one or several devices): bands of
/// whole rows, each a run of the one-launch grid's blocks in their order (the same pixels side by side
/// in time as in one launch), their heights multiples of 16 rows (a block's height), made smaller down
/// the frame as guided self-scheduling does: each band is the rows left over `streams`, so that the
/// first bands are large launches and the last ones small enough to even out the devices' finish.
/// Never below 16 rows (the last band may be less, at the frame's edge). Empty for an empty film.
std::vector<PixelRect> bandsOf(uint32_t width, uint32_t height, int streams);

} // namespace urbis
