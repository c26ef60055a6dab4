// A film's AOVs as pictures for the viewer's screen (docs/viewer.md): what each layer shows and how
// its values become 8-bit sRGB.
#pragma once

#include "film/film.h"

#include <cstdint>

namespace urbis {

/// What the viewer shows of the film.
enum class FilmDisplay : uint8_t {
    Image,     ///< the tone-mapped radiance
    Albedo,    ///< mean albedo, sRGB-encoded
    Normal,    ///< mean shading normal, each axis from [-1, 1] to [0, 1]
    Depth,     ///< z depth on a log scale: 1 m white to 10 km black; the sky black
    Ids,       ///< a colour hashed from each pixel's object and part; the sky black
    Error,     ///< heat map of the relative standard error of the pixel's mean luminance: blue 0 to red 50 %
};

/// The names of FilmDisplay's values, in order.
inline constexpr const char* kFilmDisplayNames[] = {"image", "albedo", "normal", "depth", "ids", "error"};

/// The picture of `film`'s layer `display`; Image through toneMap at `exposureEv` stops. Any other
/// layer needs a film with AOVs.
Rgb8Image displayImage(const Film& film, FilmDisplay display, float exposureEv);

} // namespace urbis
