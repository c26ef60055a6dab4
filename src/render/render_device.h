// One device a Renderer runs its passes on, with the film its camera passes add to: the CPU's thread
// pool over a host film (cpu_device.h), or one GPU over its device film (gpu_device.h). What differs
// between integrators is not here: a camera pass runs settings.integrator's camera sample, and the light
// pass is the integrator's (renderer.h). Called once a pass or a tile, never per ray: a virtual call is
// cheap here.
#pragma once

#include "cluster/tile_renderer.h"
#include "film/display_pixel.h"
#include "film/film.h"
#include "film/image.h"
#include "gpu/gpu_backend.h"
#include "integrators/photon_passes.h"
#include "integrators/render_counters.h"
#include "math/ray.h"
#include "scene/camera.h"
#include "scene/photon_view.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace urbis {

class RenderDevice {
public:
    virtual ~RenderDevice() = default;
    /// "cpu" or "cuda".
    virtual const char* kind() const = 0;
    /// The CPU's or the GPU's model name.
    virtual const std::string& name() const = 0;
    /// Makes `film` (its size, layers and sums) the one the camera passes add to: on the CPU that film
    /// itself, which must outlive the passes; on a GPU a device copy, read back by readFilm.
    virtual void setFilm(Film& film) = 0;
    /// Adds samples `samples` of every pixel to the film by settings.integrator's camera pass, which
    /// sees `photons` (what the light pass of those samples left; none for the path tracer), and the
    /// AOV pass where the film keeps AOVs. Adds its rays and seconds (the GPU's: its kernels') to
    /// `counters`. `showProgress`: a progress bar on stderr (CPU).
    virtual void cameraPass(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                            const PhotonsView& photons, bool showProgress, RenderCounters& counters) = 0;
    /// Renderers of the film's tiles on this device, `count` of them (a GPU's run on streams of their
    /// own), each adding samples `samples` seen through `photons`; the first makes the device film from
    /// the host film in startFrame.
    virtual std::vector<std::unique_ptr<TileRenderer>> tileRenderers(const Camera& camera, const RenderSettings& settings,
                                                                     SampleRange samples, const PhotonsView& photons,
                                                                     int count) = 0;
    /// How many tile renderers keep this device busy (kGpuStreamsPerDevice on a GPU).
    virtual int tileStreams() const = 0;
    /// Denoises the film in place (it must keep AOVs).
    virtual void denoise() = 0;
    /// Leaves the film's arrays in `film`.
    virtual void readFilm(Film& film) = 0;
    /// Makes the 8-bit picture of the film (film/display_pixel.h: layer `display` at `exposureEv`
    /// stops), denoised first where `denoised` (the film's sums kept), into `deviceRgba` (a GPU's mapped
    /// OpenGL buffer; the CPU has none) or, where null, for picture().
    virtual void drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba) = 0;
    /// The picture drawPicture made last into its own buffer, on the host.
    virtual Rgb8Image picture() const = 0;
    /// The light pre-pass of the photon integrators on this device, for `scene` (which must outlive it).
    virtual std::unique_ptr<PhotonPasses> photonPasses(const Scene& scene) = 0;
    /// Takes what relightWindows and lightScene changed of `scene` (the scene this device renders).
    virtual void relight(const Scene& scene) = 0;
    /// Milliseconds of `repeats` runs tracing `rays` (closest hit, or any hit when `shadow`) after
    /// `warmup` untimed ones (the GPU's: kernel times).
    virtual std::vector<float> timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats) = 0;
    /// Device memory held, by kind (zero on the CPU).
    virtual GpuMemory memory() const = 0;
};

/// `count` tile renderers, renderer i made by `make(i)`.
template <class Make>
std::vector<std::unique_ptr<TileRenderer>> tileRenderersOf(int count, Make&& make) {
    std::vector<std::unique_ptr<TileRenderer>> renderers;
    for (int i = 0; i < count; ++i) renderers.push_back(make(i));
    return renderers;
}

} // namespace urbis
