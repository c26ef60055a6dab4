// A film's layers as pictures for the viewer's screen (docs/viewer.md), made on the host pixel by
// pixel as film/display_pixel.h says.
#pragma once

#include "film/display_pixel.h"
#include "film/film.h"

#include <cstdint>

namespace urbis {

/// The names of FilmDisplay's values, in order.
inline constexpr const char* kFilmDisplayNames[] = {"image", "albedo", "normal", "depth", "ids", "error"};

/// The picture of `film`'s layer `display`; Image through toneMap at `exposureEv` stops. Any other
/// layer needs a film with AOVs.
Rgb8Image displayImage(const Film& film, FilmDisplay display, float exposureEv);

} // namespace urbis
