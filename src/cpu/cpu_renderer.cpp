#include "cpu/cpu_renderer.h"

#include "base/step_timer.h"
#include "integrators/aov_sample.h"
#include "integrators/path_samples.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace urbis {

namespace {

/// A bar on stderr redrawn when the whole percentage changes.
class ProgressBar {
public:
    ProgressBar(bool enabled, size_t total) : enabled_(enabled), total_(total) {}
    void advance(size_t amount) {
        if (!enabled_) return;
        size_t done = done_ += amount;
        int percent = int(100 * done / total_);
        std::lock_guard<std::mutex> lock(mutex_);
        if (percent == shown_) return;
        shown_ = percent;
        std::fprintf(stderr, "\rrendering [%-50.*s] %3d%%", percent / 2,
                     "##################################################", percent);
        if (done == total_) std::fputc('\n', stderr);
    }

private:
    bool enabled_;
    size_t total_;
    std::atomic<size_t> done_{0};
    std::mutex mutex_;
    int shown_ = -1;
};

/// Adds samples `samples` of the pixels of `rect` in 16x16 tiles over TBB's pool.
void renderRect(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                const PixelRect& rect, Film& film, ProgressBar& progress, RenderCounters& counters) {
    if (film.width != settings.width || film.height != settings.height)
        throw std::invalid_argument("renderCpu: the film's size is not the settings' image size");
    if (rect.x1 > film.width || rect.y1 > film.height || rect.x0 > rect.x1 || rect.y0 > rect.y1)
        throw std::invalid_argument("renderCpu: the rectangle is not inside the film");
    const FilmView view = film.view();
    std::atomic<uint64_t> rays{0};
    const auto start = SteadyClock::now();
    constexpr size_t kTile = 16;
    tbb::parallel_for(
        tbb::blocked_range2d<uint32_t>(rect.y0, rect.y1, kTile, rect.x0, rect.x1, kTile),
        [&](const tbb::blocked_range2d<uint32_t>& tile) {
            uint64_t tileRays = 0;
            for (uint32_t y = tile.rows().begin(); y < tile.rows().end(); ++y)
                for (uint32_t x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                    tileRays += addPathSamples(scene, camera, settings, x, y, samples, view);
                    if (view.hasAovs()) addAovSamples(scene, camera, settings, x, y, samples, view);
                }
            rays += tileRays;
            progress.advance(tile.rows().size() * tile.cols().size());
        },
        tbb::simple_partitioner());
    counters.seconds = secondsSince(start);
    counters.rays = rays;
}

} // namespace

void renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
               Film& film, bool showProgress, RenderCounters& counters) {
    ProgressBar progress(showProgress, film.pixels());
    renderRect(scene, camera, settings, samples, PixelRect{0, 0, film.width, film.height}, film, progress, counters);
}

void renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
               const PixelRect& rect, Film& film, RenderCounters& counters) {
    ProgressBar progress(false, rect.pixels());
    renderRect(scene, camera, settings, samples, rect, film, progress, counters);
}

LinearImage renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                      bool showProgress, RenderCounters& counters) {
    Film film(settings.width, settings.height, false);
    renderCpu(scene, camera, settings, SampleRange{0, settings.spp}, film, showProgress, counters);
    return meanRadiance(film);
}

std::vector<uint32_t> renderIdsCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings) {
    std::vector<uint32_t> ids(size_t(settings.width) * settings.height);
    tbb::parallel_for(uint32_t(0), settings.height, [&](uint32_t y) {
        for (uint32_t x = 0; x < settings.width; ++x)
            ids[size_t(y) * settings.width + x] = primaryHitId(scene, camera, settings, x, y);
    });
    return ids;
}

} // namespace urbis
