#include "film/aov_display.h"

#include <tbb/parallel_for.h>

#include <stdexcept>

namespace urbis {

Rgb8Image displayImage(const Film& film, FilmDisplay display, float exposureEv) {
    if (display != FilmDisplay::Image && !film.hasAovs())
        throw std::invalid_argument("displayImage: the film keeps no AOVs to show");
    Rgb8Image out{film.width, film.height, std::vector<uint8_t>(film.pixels() * 3)};
    const FilmView view = const_cast<Film&>(film).view();   // displayPixel only reads it
    const float scale = std::exp2(exposureEv);
    // Rows in parallel: the viewer makes a picture every frame (each pixel alone, so any thread count agrees).
    tbb::parallel_for(uint32_t(0), film.height, [&](uint32_t y) {
        for (size_t i = size_t(y) * film.width; i < size_t(y + 1) * film.width; ++i)
            displayPixel(view, display, scale, i, &out.rgb[3 * i]);
    });
    return out;
}

} // namespace urbis
