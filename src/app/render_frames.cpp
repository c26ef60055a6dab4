#include "app/render_frames.h"

#include "base/step_timer.h"
#include "cluster/frame_spread.h"
#include "cluster/tile_queue.h"
#include "cluster/tile_workers.h"

#include "animation/animation_timeline.h"
#include "animation/frame_range.h"
#include "app/video_encoding.h"
#include "base/input_error.h"
#include "prepare/scene_lighting.h"
#include "description/scene_parts.h"
#include "film/film_output.h"
#include "render/renderer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <unistd.h>

namespace urbis {

namespace {

FrameRange frameRangeOf(const RenderOptions& o) {
    std::string error;
    const std::optional<FrameRange> range = parseFrameRange(o.frames.frames, frameCountOf(o.scene.animation), error);
    if (!range) throw InputError("--frames: " + error, FailureKind::Usage);
    return *range;
}

/// "2 min 5 s", "42 s": a duration as the progress line says it.
std::string durationText(double seconds) {
    const long s = std::lround(seconds);
    if (s < 60) return std::to_string(s) + " s";
    if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
    return std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
}

/// This rank's share of `frames`: all of them in one process. Every rank lists the frames still to
/// render before any writes one (the barrier), so that all ranks share out the same list.
std::vector<uint32_t> framesOfThisRank(const std::vector<uint32_t>& frames, const MpiWorld* world) {
    if (!world || world->ranks() < 2) return frames;
    world->barrier();
    return framesOfRank(frames, world->rank(), world->ranks());
}

} // namespace

void checkFrameOptions(const RenderOptions& o) {
    const std::string& pattern = o.scene.film.output;
    if (o.scene.animation.empty())
        throw InputError("--frames: the scene has no animation (animation.camera or animation.time keyframes, docs/animation.md)",
                         FailureKind::Usage);
    std::string error;
    if (!isFramePattern(pattern, error)) throw InputError("--out (film.output) with --frames: " + error, FailureKind::Usage);
    frameRangeOf(o);
    if (!o.run.statsFile.empty()) throw InputError("--stats: counts one still; not with --frames", FailureKind::Usage);
    if (!o.frames.video.empty()) checkVideoOutput(o.frames.video, pattern);
    const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::create_directories(folder, ec) && ec)
        throw InputError(folder.string() + ": cannot make the frames' folder (" + ec.message() + ")", FailureKind::Output);
}

void renderFrames(const RenderOptions& o, PreparedScene& prepared, const std::vector<int>& gpus, const MpiWorld* world) {
    const auto start = SteadyClock::now();
    const FilmDescription& film = o.scene.film;
    const std::string& pattern = film.output;
    const FrameRange range = frameRangeOf(o);
    const std::vector<uint32_t> frames = framesOfThisRank(framesToRender(range, pattern, o.frames.overwrite), world);
    const AnimationTimeline timeline(o.scene, prepared.origin);
    const bool timeMoves = !o.scene.animation.time.empty();
    const uint32_t layers = filmLayerMaskOf(film.layers);
    const bool aovs = film.denoise || filmOutputNeedsAovs(pattern, layers);
    const RenderSettings settings = renderSettingsOf(o.scene);
    std::printf("urbis: frames %u..%u: %zu to render, %zu kept\n", range.first, range.last, frames.size(),
                size_t(range.count()) - frames.size());
    std::fflush(stdout);

    // The scene goes to each GPU once, before the first frame: one renderer a device of --devices, each
    // rendering whole frames; else one, on the GPU of this rank's local rank under mpirun.
    const size_t filmBytes = Film::bytesFor(settings.width, settings.height, aovs);
    std::vector<std::unique_ptr<Renderer>> renderers;
    const auto rendererOn = [&](const std::string& device, const std::vector<int>& on) {
        renderers.push_back(Renderer::make(prepared.scene, settings.integrator, {device, on, filmBytes, o.run.verbose, nullptr}));
    };
    if (gpus.size() > 1) {
        for (int gpu : gpus) rendererOn("cuda", {gpu});
    } else {
        const bool rankGpu = gpus.empty() && world && world->ranks() > 1 && o.run.device == "cuda";
        rendererOn(gpus.empty() ? o.run.device : "cuda", rankGpu ? std::vector<int>{gpuOfRank(*world)} : gpus);
    }

    // Frames go to the renderers from one queue. The host scene is relit and the lights uploaded under
    // the lock (another device's frame may be relighting it); the render then reads only its device.
    std::mutex lock;
    TileQueue queue(frames.size());
    size_t done = 0;
    double secondsRendering = 0;
    std::string device = "cpu";
    const bool showProgress = isatty(2) && renderers.size() == 1;
    runOnWorkerThreads(renderers.size(), [&](size_t b) {
        Renderer& renderer = *renderers[b];
        for (int32_t i; (i = queue.take()) >= 0;) {
            const auto t0 = SteadyClock::now();
            const uint32_t n = frames[size_t(i)];
            Camera camera;
            FilmOutputOptions output;
            {
                const std::lock_guard<std::mutex> held(lock);
                const SceneDescription d = timeline.frame(n);
                if (timeMoves) {   // only the lights and the sky: the geometry and its BVH stay as built
                    relightWindows(prepared.scene, prepared.windowUses, hourOf(d));
                    lightScene(prepared.scene, d, prepared.origin);
                    renderer.relight();
                }
                camera = cameraOf(d.camera, float(film.width) / float(film.height), prepared.origin, prepared.framingPieces,
                                  groundOf(prepared.scene));
                output = FilmOutputOptions{d.film.exposure, film.exrFloat, layers};
            }
            renderer.startAfresh();
            Film image(settings.width, settings.height, aovs);
            RenderCounters counters;
            DeviceReport report;
            renderer.render(camera, settings, image.nextSamples(settings.spp), image, film.denoise, showProgress, counters, report);
            const std::string path = framePath(pattern, n);
            writeFilm(image, path, output);
            const double seconds = secondsSince(t0);
            const std::lock_guard<std::mutex> held(lock);
            device = report.device;
            secondsRendering += seconds;
            ++done;
            const double left = secondsRendering / double(done) * double(frames.size() - done) / double(renderers.size());
            std::printf("urbis: frame %u (%zu of %zu) %s in %.2f s, about %s left\n", n, done, frames.size(), path.c_str(),
                        seconds, durationText(left).c_str());
            std::fflush(stdout);
        }
    });
    if (world && world->ranks() > 1) world->barrier();   // every frame written before the video reads them
    if (!o.frames.video.empty() && (!world || world->isRoot())) {
        encodeVideo(pattern, range, o.scene.animation.fps, o.frames.video);
        std::printf("urbis: wrote %s (frames %u..%u at %g fps)\n", o.frames.video.c_str(), range.first, range.last,
                    double(o.scene.animation.fps));
    }
    std::printf("urbis: wrote %zu frames of %s (%ux%u, %u spp, %s) in %.2f s\n", frames.size(), pattern.c_str(),
                settings.width, settings.height, settings.spp, device.c_str(),
                secondsSince(start));
}

} // namespace urbis
