// The viewer's render loop: one sample per pixel a frame added to a film on the GPU (when usable)
// or the CPU by the scene's integrator (a Renderer, whose state, such as the photon buffers, lives
// across restarts), started over on any change, and the film made into a picture where it is (the
// GPU's picture kernel, or film/aov_display.h on the CPU), denoised while it is young.
#pragma once

#include "film/aov_display.h"
#include "film/film.h"
#include "integrators/render_counters.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

#include <memory>
#include <string>

namespace urbis {

class ProgressiveRenderer {
public:
    /// Up to this many samples per pixel the picture is denoised (where the scene asks for it): the
    /// filter's gain is largest on a young image, and its cost is then paid on few frames.
    static constexpr uint32_t kDenoiseUntil = 64;

    /// Renders `scene` (which must outlive this) on `deviceChoice` ("auto", "cpu" or "cuda", as Renderer
    /// picks; "cuda" without a usable GPU throws InputError) by `integrator`.
    ProgressiveRenderer(const Scene& scene, IntegratorKind integrator, const std::string& deviceChoice, bool verbose);
    ~ProgressiveRenderer();

    /// Starts a fresh film of settings' size (with AOVs `aovs`) seen by `camera`, rendered by
    /// settings.integrator (a renderer made anew where it is another than before).
    void restart(const Camera& camera, const RenderSettings& settings, bool aovs);
    /// Adds the next sample of every pixel; counters hold its rays and seconds.
    void addSample(RenderCounters& counters);
    /// Samples per pixel so far.
    uint32_t samples() const { return samples_; }
    /// Whether the film keeps AOVs.
    bool hasAovs() const { return film_.hasAovs(); }
    /// The film as accumulated (copied from the GPU first where it renders there).
    const Film& film();
    /// Makes the picture of the film: `display` at `exposureEv`, denoised first with `denoise` while
    /// samples() < kDenoiseUntil. On the GPU it stays there: in `deviceRgba` (width x height x 4
    /// bytes of device memory: a mapped OpenGL pixel buffer) or, where null, for picture() to copy.
    void makePicture(FilmDisplay display, float exposureEv, bool denoise, uint8_t* deviceRgba = nullptr);
    /// The picture makePicture made last (with no deviceRgba), on the host.
    Rgb8Image picture() const { return renderer_->picture(); }

    std::string device() const { return renderer_->deviceKind(); }   ///< "cpu" or "cuda"
    const std::string& deviceName() const { return renderer_->deviceName(); }
    /// Device memory held (zero on the CPU).
    size_t deviceBytes() const { return renderer_->memory().total(); }

private:
    const Scene& scene_;
    std::string deviceChoice_;
    bool verbose_;
    IntegratorKind integrator_;
    std::unique_ptr<Renderer> renderer_;
    Camera camera_;
    RenderSettings settings_;
    Film film_;                 ///< on the GPU: its size and layers, its sums only when film() copied them
    uint32_t samples_ = 0;
    bool filmCurrent_ = true;   ///< film_ holds the device's samples
};

} // namespace urbis
