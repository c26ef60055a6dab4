// The GPU backend's host interface, the same whether or not urbis was built with CUDA: the
// build picks gpu_backend.cu (CUDA) or gpu_backend_none.cpp (reports "built without CUDA").
// Per-ray code is not here: the kernels call the same URBIS_HD headers as the CPU backend.
#pragma once

#include "film/denoise_filter.h"
#include "film/display_pixel.h"
#include "film/film.h"
#include "film/pixel_rect.h"
#include "integrators/photon_passes.h"
#include "integrators/render_counters.h"
#include "math/ray.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "geometry/scene_intersect.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace urbis {

/// Whether a usable GPU is there, and which.
struct GpuInfo {
    bool available = false;
    std::string name;          ///< e.g. "NVIDIA H100 80GB HBM3"; empty if unavailable
    std::string reason;        ///< why not, if unavailable ("urbis was built without CUDA", "no CUDA device: ...")
    size_t totalBytes = 0, freeBytes = 0;
    int computeMajor = 0, computeMinor = 0, multiprocessors = 0;
};

/// Probes CUDA device `device` (and makes it the calling thread's). Never throws; a missing driver or
/// device is reported in `reason`.
GpuInfo probeGpu(int device = 0);

/// How many CUDA devices this machine has: 0 without a driver, a device or a CUDA build.
int gpuDeviceCount();

/// Device memory held by a GpuScene (bytes): the scene's arrays, the film (with the viewer's picture) and the ray buffers.
struct GpuMemory {
    SceneMemory scene;
    size_t film = 0, rays = 0;
    size_t total() const { return scene.total() + film + rays; }
};

/// A Scene mirrored on the GPU (flat POD arrays, as they are on the host), with the kernels
/// that use it. Every failure (no device, too little memory, a failed launch) throws
/// InputError with a one-line message naming the CUDA call and its error string.
class GpuScene {
public:
    /// Uploads `scene` to CUDA device `device` after checking with cudaMemGetInfo that it fits (with
    /// `extraBytes` more for film or ray buffers the caller will need). Every call on the GpuScene
    /// works on that device, from whichever host thread makes it.
    static std::unique_ptr<GpuScene> upload(const Scene& scene, size_t extraBytes = 0, int device = 0);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    /// Makes the device film a copy of `film` (its size, AOVs and sums): render calls add to it,
    /// and it stays on the device between them.
    void setFilm(const Film& film);
    /// Adds samples `samples` of every pixel to the device film, like renderCpu: the render kernel of
    /// settings.integrator (whose camera pass sees `photons`, what its photon pass left), then the AOV
    /// pass's when the film keeps AOVs. The film must be settings.width x settings.height.
    /// counters.seconds is the kernels' time (CUDA events).
    void render(const Camera& camera, const RenderSettings& settings, SampleRange samples, RenderCounters& counters,
                const PhotonsView& photons = {});
    /// Uploads again what lightScene and relightWindows change of `scene` (the scene this GpuScene was
    /// uploaded from, relit for another time of day): the walls' lit windows, the light list, the sky's
    /// tables, the sun, sky and night records. The geometry and its BVH stay on the device as they are.
    void relight(const Scene& scene);
    /// Denoises the device film in place, as denoiseCpu does the host film (the same per-pixel
    /// passes of film/denoise_filter.h, one kernel each). The film must keep AOVs.
    void denoise(const DenoiseParams& params = {});
    /// Copies the device film into `film`.
    void readFilm(Film& film) const;
    /// Makes the 8-bit sRGB picture of the device film on the device (film/display_pixel.h: layer
    /// `display` at `exposureEv` stops), denoised first where `denoised` (the film's sums are kept, to
    /// go on adding samples), into `rgba`: device memory of width x height x 4 bytes, rows from the
    /// top (an OpenGL pixel buffer that CUDA has mapped), or where null this GpuScene's own RGB
    /// picture, for readPicture. Returns when the picture is written.
    void drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* rgba = nullptr);
    /// The picture drawPicture made last into its own buffer, copied to the host (RGB, 8 bits a channel).
    Rgb8Image readPicture() const;
    /// The mean radiance of a fresh device film of settings.spp samples per pixel, like renderCpu's.
    LinearImage render(const Camera& camera, const RenderSettings& settings, RenderCounters& counters);

    /// The closest surface (intersectScene: every primitive kind and the ground) of every ray.
    std::vector<SurfaceHit> intersect(const std::vector<Ray>& rays);
    /// Whether each ray is blocked by anything (occludedScene); 1 or 0.
    std::vector<uint8_t> occluded(const std::vector<Ray>& rays);

    /// Kernel times in milliseconds of `repeats` launches tracing `rays` (closest hit, or
    /// any hit when `shadow`), after `warmup` untimed launches. Rays stay on the device.
    std::vector<float> timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats);
    /// The photon integrators' light pre-pass on this device (gpu_photons.h), for the host `scene` this
    /// GpuScene was uploaded from: its photons and buffers live as long as the returned object, which
    /// must not outlive this GpuScene.
    std::unique_ptr<PhotonPasses> photonPasses(const Scene& scene);
    /// The device scene as the kernels see it (device pointers), with this GpuScene's device made the
    /// calling thread's: for the passes of gpu_photons.h.
    SceneView deviceView() const;

    /// Device memory held now, by kind.
    GpuMemory memory() const;
    /// The device's name and facts, as probed when uploading.
    const GpuInfo& info() const;

    struct Impl;

private:
    friend class GpuTileStream;
    explicit GpuScene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

/// Renders tiles of a GpuScene's device film on a CUDA stream of its own, with its own ray counter.
/// A 256-pixel tile is about one wave of blocks on an H200, so one launch at a time would leave SMs
/// idle under each tile's slowest pixels; tiles on several streams of one device run at once, and the
/// next tile's blocks take those SMs. Each stream is driven by one host thread at a time; its GpuScene
/// must outlive it.
class GpuTileStream {
public:
    explicit GpuTileStream(GpuScene& gpu);
    ~GpuTileStream();
    GpuTileStream(GpuTileStream&&) noexcept;
    GpuTileStream(const GpuTileStream&) = delete;
    GpuTileStream& operator=(const GpuTileStream&) = delete;
    GpuTileStream& operator=(GpuTileStream&&) = delete;

    /// Adds samples `samples` of the pixels of `tile` to the device film (GpuScene::setFilm's), as
    /// GpuScene::render does for every pixel, then copies those pixels of every film array into the same
    /// rectangle of `film` (the device film's size and layers; its other pixels left as they are).
    /// Returns the rays traced. A pixel's bits do not depend on the tiles or streams the frame is
    /// rendered in: the sampler is keyed by pixel. `photons`: as GpuScene::render's.
    uint64_t renderTile(const Camera& camera, const RenderSettings& settings, SampleRange samples, const PixelRect& tile,
                        Film& film, const PhotonsView& photons = {});

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace urbis
