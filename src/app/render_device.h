// Choosing the backend of a render (--device auto|cpu|cuda, --devices) and running it there.
#pragma once

#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_photons.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_backend.h"

#include <memory>
#include <string>
#include <vector>

namespace urbis {

/// Where a frame was rendered and what it held there.
struct DeviceReport {
    std::string device = "cpu";   ///< "cpu" or "cuda"
    std::string name;             ///< the GPU's or the CPU's model name ("N x name" over several GPUs)
    GpuMemory memory;             ///< device memory by kind, of the first GPU (zero on the CPU)
    double secondsDenoise = 0;    ///< wall time of the denoiser (zero without)
    PhotonTimings photons;        ///< the photon integrators' passes (zero for the path tracer)
    std::vector<uint32_t> tilesByDevice;   ///< the bands each GPU of `--devices` rendered (empty for one device)
};

/// The CPU's model name from /proc/cpuinfo, or "cpu" where unknown.
std::string cpuModelName();

/// The CUDA devices of `--devices` (`devices`; empty without it), checked before any work: refused
/// with `--device cpu` and, over several devices, with a photon integrator (usage: their photon passes
/// span the frame); "built without CUDA", no device or an index this machine lacks (device).
std::vector<int> devicesOf(const std::string& devices, const std::string& device, IntegratorKind integrator);

/// The backend of a run, chosen once and kept for every frame it renders: the GPUs the scene was
/// uploaded to (once each, so that the frames of a sequence share one upload), or the CPU.
class RenderBackend {
public:
    /// Chooses where `scene` (which must outlive this) renders: `device` "cuda" (InputError if a GPU
    /// cannot take the scene), "cpu", or "auto" (the GPU when usable, else the CPU, with a stated
    /// fallback where the upload fails). `gpus`: the CUDA devices (empty: device 0); several need
    /// "cuda". Uploads the scene to each, with room checked for a film of `filmBytes`. Which device
    /// renders is said on stderr when `verbose` or when "cuda" was asked for.
    RenderBackend(const Scene& scene, const std::string& device, const std::vector<int>& gpus, size_t filmBytes, bool verbose);
    ~RenderBackend();
    RenderBackend(const RenderBackend&) = delete;
    RenderBackend& operator=(const RenderBackend&) = delete;

    /// Adds `samples` of every pixel to `film`: on one GPU in one launch, over several GPUs in bands
    /// (bandsOf) from one queue, on kGpuStreamsPerDevice streams of each (renderTilesOnWorkers: the same
    /// pixels, bit for bit), on the CPU by renderCpu or renderPhotonsCpu (`showProgress`: its progress bar). With
    /// `denoise` (the film must keep AOVs) the first device then denoises the film in place. "auto"
    /// falls back to the CPU if the GPU fails, `film` then as it was.
    void render(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film, bool denoise,
                bool showProgress, RenderCounters& counters, DeviceReport& report);
    /// Uploads to every GPU what relightWindows and lightScene changed of the scene (GpuScene::relight):
    /// call after relighting it for another time of day, before the next render.
    void relight();

private:
    void renderOnGpus(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film, bool denoise,
                      RenderCounters& counters, DeviceReport& report);

    const Scene& scene_;
    std::string device_;
    std::vector<std::unique_ptr<GpuScene>> gpus_;   ///< empty: the CPU renders
};

/// Adds `samples` of every pixel to `film` on `device` through a RenderBackend made for this one frame
/// (device 0 where a GPU renders); see RenderBackend.
void renderOnDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                    Film& film, bool denoise, const std::string& device, bool showProgress, bool verbose,
                    RenderCounters& counters, DeviceReport& report);

} // namespace urbis
