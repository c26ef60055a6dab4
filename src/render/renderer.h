// The one object every front-end drives (`render`, `bench`, the viewer, `--frames`, MPI ranks,
// `--devices`): a Renderer per integrator, made by Renderer::make. It owns the devices a render runs
// on and its integrator's passes and their state across calls (the photon buffers persist between
// frames). A render is a list of rounds: each round's light pass, where the
// integrator has one, runs on every device before that round's camera pass, over the whole frame on
// one device, in bands from one queue over several GPUs (`--devices`), or in tiles across the ranks
// of an MPI job; the front-ends never ask which integrator they run.
#pragma once

#include "cluster/mpi_world.h"
#include "integrators/photon_timings.h"
#include "render/render_device.h"
#include "scene/integrator_choice.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// Where a frame was rendered and what it held there.
struct DeviceReport {
    std::string device = "cpu";   ///< "cpu" or "cuda"
    std::string name;             ///< the GPU's or the CPU's model name ("N x name" over several GPUs)
    GpuMemory memory;             ///< device memory by kind, of the first GPU (zero on the CPU)
    double secondsDenoise = 0;    ///< wall time of the denoiser (zero without)
    std::optional<PhotonTimings> photons;   ///< the photon integrators' passes (none for the path tracer)
    std::vector<uint32_t> tilesByDevice;    ///< the bands each GPU of `--devices` rendered (empty for one device)
    std::vector<uint32_t> tilesByRank;      ///< the tiles each MPI rank rendered (empty outside mpirun)
};

/// Where a Renderer runs.
struct RendererOptions {
    std::string device = "auto";    ///< "cuda" (InputError where no GPU takes the scene), "cpu", or "auto"
                                    ///< (the GPU when usable, else the CPU, with a stated fallback)
    std::vector<int> gpus;          ///< the CUDA devices (empty: device 0); several need "cuda"
    size_t filmBytes = 0;           ///< room checked on each GPU for the film
    bool verbose = false;           ///< say on stderr which device renders (always with "cuda")
    const MpiWorld* world = nullptr;   ///< of more than one rank: frames shared among the ranks in tiles, each
                                       ///< rank on its CPU or (with "cuda") the GPU of its local rank
};

/// The GPU a rank takes under mpirun: that of its local rank (InputError where the machine has none).
int gpuOfRank(const MpiWorld& world);

class Renderer {
public:
    /// The renderer of `integrator` for `scene` (which must outlive it), its devices chosen by `options`.
    static std::unique_ptr<Renderer> make(const Scene& scene, IntegratorKind integrator, const RendererOptions& options);
    virtual ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Adds `samples` of every pixel to `film` (settings' size): on one device as it is, over several
    /// GPUs in bands (bandsOf) on kGpuStreamsPerDevice streams each, across MPI ranks in tiles; every
    /// way gives the same pixels, bit for bit, for devices of one kind. With `denoise` (the film must
    /// keep AOVs) the first device then denoises the film. "auto" falls back to the CPU where the GPU
    /// fails, `film` then as it was. `showProgress`: the CPU's progress bar.
    void render(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film, bool denoise,
                bool showProgress, RenderCounters& counters, DeviceReport& report);

    /// Progressive rendering on the first device (the viewer): makes `film` the one addSamples adds to
    /// (on a GPU a device copy that stays there).
    void startFilm(Film& film);
    /// Adds `samples` to the film of startFilm; `counters` get their rays and seconds.
    void addSamples(const Camera& camera, const RenderSettings& settings, SampleRange samples, RenderCounters& counters);
    /// Leaves the film of startFilm in `film`.
    void readFilm(Film& film);
    /// The picture of the film of startFilm (RenderDevice::drawPicture).
    void drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba = nullptr);
    Rgb8Image picture() const;

    /// Milliseconds of `repeats` frames of settings.spp samples (light and camera passes; the GPU's
    /// kernel times) on the first device after `warmup` untimed ones, into a film of its own.
    std::vector<float> timeFrames(const Camera& camera, const RenderSettings& settings, int warmup, int repeats);
    /// Milliseconds of tracing `rays` on the first device (RenderDevice::timeTrace).
    std::vector<float> timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats);

    /// Takes what relightWindows and lightScene changed of the scene, on every device, and forgets
    /// what the integrator's state owed to the old lights: call after relighting, before the next render.
    void relight();

    /// Forgets what the integrator kept from the calls before (the photon buffers), so that the next
    /// render is the one a fresh Renderer gives: a sequence's frame, whichever renderer takes it.
    void startAfresh() { forgetState(); }

    /// "cpu" or "cuda": where the first device renders.
    const char* deviceKind() const { return devices_[0]->kind(); }
    /// The first device's model name.
    const std::string& deviceName() const { return devices_[0]->name(); }
    /// Device memory of the first device with what the integrator keeps there.
    GpuMemory memory() const;

protected:
    Renderer(const Scene& scene, const RendererOptions& options);

    /// Whether the integrator has a light pass: then every sample is a round of its own.
    virtual bool hasLightPass() const = 0;
    /// The light pass of sample `sample` on device `device` (an index of devices()): what its camera
    /// pass then sees. Times and counts go to `timings`.
    virtual PhotonsView lightPass(size_t device, const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                  PhotonTimings& timings) = 0;
    /// After a render's last round on device 0, whose light pass left `last` for sample `sample`: what
    /// the report says of the passes (`timings` as they added up; none for an integrator without).
    virtual std::optional<PhotonTimings> reportPasses(const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                                      const PhotonsView& last, PhotonTimings timings) = 0;
    /// Forgets what the integrator keeps for the lights and devices it had (after relight or a fallback).
    virtual void forgetState() = 0;
    /// Host or device bytes of that state on device 0.
    virtual size_t stateBytes() const = 0;

    const Scene& scene() const { return scene_; }
    std::vector<std::unique_ptr<RenderDevice>>& devices() { return devices_; }

private:
    /// The rounds `samples` are rendered in (one, or one a sample).
    std::vector<SampleRange> roundsOf(SampleRange samples) const;
    /// The light and camera passes of `samples` on device 0 into its film; returns what the last light
    /// pass left (for reportPasses).
    PhotonsView passesOnFirst(const Camera& camera, const RenderSettings& settings, SampleRange samples, bool showProgress,
                              RenderCounters& counters, PhotonTimings& timings);
    /// lightPass, its seconds and photon rays also added to `counters`.
    PhotonsView countedLightPass(size_t device, const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                 RenderCounters& counters, PhotonTimings& timings);
    void renderOnOne(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film, bool denoise,
                     bool showProgress, RenderCounters& counters, DeviceReport& report);
    void renderOnDevices(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                         bool denoise, RenderCounters& counters, DeviceReport& report);
    void renderAcrossRanks(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                           bool denoise, RenderCounters& counters, DeviceReport& report);
    /// Where `denoise`: denoises on the first device (`film` made its film first where `upload`) and
    /// leaves the result in `film`; seconds.
    double denoiseOnFirst(Film& film, bool denoise, bool upload);

    const Scene& scene_;
    RendererOptions options_;
    std::vector<std::unique_ptr<RenderDevice>> devices_;
};

} // namespace urbis
