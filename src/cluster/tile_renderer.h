// What renders the tiles of one frame for a tile queue: the CPU's thread pool or one GPU
// (app/tile_renderers.h). Called once a tile, never per ray: a virtual call is cheap here.
#pragma once

#include "film/film.h"
#include "film/pixel_rect.h"

#include <cstdint>

namespace urbis {

/// Renders the tiles of one frame (its camera, settings and samples fixed at construction).
class TileRenderer {
public:
    virtual ~TileRenderer() = default;
    /// Starts the frame whose samples add to `film` (its size, layers and sums so far), before any tile.
    virtual void startFrame(const Film& film) = 0;
    /// Adds the frame's samples of the pixels of `tile` and leaves those pixels, every array, in the
    /// same rectangle of `film` (the one startFrame was given; other pixels untouched, so that threads
    /// may render disjoint tiles of one film at once). Returns the rays traced.
    virtual uint64_t renderTile(const PixelRect& tile, Film& film) = 0;
};

} // namespace urbis
