// Multi-layer OpenEXR output of a film: linear RGBA and the AOVs as named layers (docs/film.md).
#pragma once

#include "film/film.h"
#include "film/film_layers.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace urbis {

/// How a film's EXR is written.
struct ExrOptions {
    float exposureScale = 1.0f;   ///< multiplies the mean radiance (2^exposure)
    bool floatColour = false;     ///< RGBA, albedo and normal as 32-bit float; otherwise half
    uint32_t layers = kAllFilmLayers;  ///< which AOV layer groups (film_layers.h) a film with AOVs writes
};

/// Writes `film` to `path` through a temporary beside it, then renamed: R, G, B, A (A = 1), and
/// when the film keeps AOVs, of the groups in options.layers, albedo.R/G/B, normal.X/Y/Z, depth.Z and position.X/Y/Z (float),
/// id.object, id.part and samples (uint). ZIP-compressed scan lines. Throws InputError naming the
/// file on failure.
void writeExr(const Film& film, const std::string& path, const ExrOptions& options);

/// Host bytes writeExr holds beside the film for a `width` x `height` image with AOVs.
size_t exrWriteBytes(uint32_t width, uint32_t height);

} // namespace urbis
