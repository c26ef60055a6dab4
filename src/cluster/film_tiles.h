// A film's pixels in one rectangle as bytes, the message a rank sends rank 0 for each tile it rendered.
#pragma once

#include "film/film.h"
#include "film/pixel_rect.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Every per-pixel array the film keeps (forEachFilmArray's order), the pixels of `rect` row by
/// row, as raw bytes: the exact bits, so that rank 0's film is the one that rendered them.
std::vector<uint8_t> packFilmRect(const Film& film, const PixelRect& rect);

/// Writes bytes of packFilmRect into the same rectangle of `film` (of the same size and layers).
/// Throws std::invalid_argument when the byte count does not fit the rectangle.
void unpackFilmRect(const std::vector<uint8_t>& bytes, const PixelRect& rect, Film& film);

} // namespace urbis
