#include "cpu/cpu_denoiser.h"

#include "scene/surface_part.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <utility>
#include <vector>

namespace urbis {

static_assert(kDenoisePartBits == kSurfacePartBits, "the denoiser's ids pack parts as surface ids do");

namespace {

/// Calls `f(x, y)` for every pixel of a `width` x `height` image, rows in parallel.
template <class F>
void forEachPixel(uint32_t width, uint32_t height, F&& f) {
    tbb::parallel_for(uint32_t(0), height, [&](uint32_t y) {
        for (uint32_t x = 0; x < width; ++x) f(x, y);
    });
}

} // namespace

void denoiseCpu(Film& film, const DenoiseParams& params) {
    if (!film.hasAovs()) throw std::invalid_argument("denoiseCpu: the film keeps no AOVs to guide the filter");
    const FilmView view = film.view();
    std::vector<DenoiseGuide> guide(film.pixels());
    std::vector<DenoiseSignal> signal(film.pixels()), next(film.pixels());
    forEachPixel(film.width, film.height, [&](uint32_t x, uint32_t y) {
        const size_t p = view.pixel(x, y);
        prepareDenoise(view, x, y, guide[p], signal[p]);
    });
    for (uint32_t i = 0; i < params.iterations; ++i) {
        const DenoiseBuffers buffers{film.width, film.height, guide.data(), signal.data(), next.data()};
        forEachPixel(film.width, film.height, [&](uint32_t x, uint32_t y) {
            next[view.pixel(x, y)] = denoiseStep(buffers, x, y, 1 << i, params);
        });
        std::swap(signal, next);
    }
    forEachPixel(film.width, film.height, [&](uint32_t x, uint32_t y) {
        const size_t p = view.pixel(x, y);
        finishDenoise(view, x, y, guide[p], signal[p]);
    });
}

} // namespace urbis
