// A film to a file, the format following the extension: .png (tone-mapped sRGB) or .exr
// (linear RGBA and the AOVs).
#pragma once

#include "film/film.h"
#include "film/film_layers.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace urbis {

enum class FilmFormat { Png, Exr };

/// How a film becomes a file.
struct FilmOutputOptions {
    float exposureEv = 0.0f;   ///< stops: PNG before its tone curve, EXR as a plain scale
    bool exrFloat = false;     ///< EXR colour, albedo and normal as float rather than half
    uint32_t exrLayers = kAllFilmLayers;  ///< the AOV layer groups an EXR holds (film_layers.h)
};

/// The format of `path` by its extension, in any case. Throws a usage InputError naming the path
/// for any other extension.
FilmFormat filmFormatOf(const std::string& path);

/// Whether the file at `path` holds AOVs (an EXR with any of the `exrLayers`), so that the render
/// must run the AOV pass.
bool filmOutputNeedsAovs(const std::string& path, uint32_t exrLayers = kAllFilmLayers);

/// The film's mean radiance at `exposureEv` (stops) through the filmic curve to 8-bit sRGB, pixel
/// by pixel (no image of means in between).
Rgb8Image toneMap(const Film& film, float exposureEv);

/// Writes `film` to `path` in the format of its extension, through a temporary renamed into
/// place. PNG: mean radiance at `options.exposureEv` through the filmic curve to 8-bit sRGB.
/// EXR: writeExr. Throws InputError naming the file on failure.
void writeFilm(const Film& film, const std::string& path, const FilmOutputOptions& options);

/// Host bytes of a `width` x `height` frame from render to file: the film (with its AOVs where an
/// EXR writes them, `withAovs`, or the denoiser reads them, `denoise`), the denoiser's buffers and
/// what writing the file holds beside the film.
size_t hostFilmBytes(uint32_t width, uint32_t height, bool withAovs = false, bool denoise = false);

} // namespace urbis
