// One frame over the devices of one process: a host thread per worker (each of a GPU's streams), all
// taking tiles from one queue and leaving their pixels in one film (`urbis render --devices`,
// docs/multi_gpu.md).
#pragma once

#include "cluster/tile_queue.h"
#include "cluster/tile_renderer.h"
#include "film/film.h"
#include "film/pixel_rect.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace urbis {

/// Runs `work(w)` for w = 0..workers-1, each on a host thread of its own (one per worker), and returns
/// when all have; a failure (an exception) of any is rethrown then.
void runOnWorkerThreads(size_t workers, const std::function<void(size_t)>& work);

/// Renders `tiles` of `film` with `workers`, one host thread each: every thread starts the frame on
/// its worker, then takes the next tile from one TileQueue until none is left, so that faster devices
/// render more. On return `film` holds every tile's pixels, bit for bit those one renderer gives the
/// same tiles. A worker's failure (an exception) is rethrown once every thread has stopped.
TileShare renderTilesOnWorkers(const std::vector<TileRenderer*>& workers, const std::vector<PixelRect>& tiles, Film& film);

} // namespace urbis
