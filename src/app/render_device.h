// Choosing the backend of a render (--device auto|cpu|cuda) and running it there.
#pragma once

#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_photons.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_backend.h"

#include <string>

namespace urbis {

/// Where a frame was rendered and what it held there.
struct DeviceReport {
    std::string device = "cpu";   ///< "cpu" or "cuda"
    std::string name;             ///< the GPU's or the CPU's model name
    GpuMemory memory;             ///< device memory by kind (zero on the CPU)
    double secondsDenoise = 0;    ///< wall time of the denoiser (zero without)
    PhotonTimings photons;        ///< the photon integrators' passes (zero for the path tracer)
};

/// The CPU's model name from /proc/cpuinfo, or "cpu" where unknown.
std::string cpuModelName();

/// Adds `samples` of every pixel to `film` on `device`: "cuda" (fails with InputError if the GPU
/// cannot), "cpu", or "auto" (the GPU when one is usable, else the CPU, with a stated fallback to
/// the CPU if the GPU fails, `film` then as it was). With `denoise` (the film must keep AOVs), the
/// same device then denoises the film in place (denoiseCpu, GpuScene::denoise). Which device renders
/// is said on stderr when `verbose` or when "cuda" was asked for. `showProgress` draws the CPU
/// progress bar.
void renderOnDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                    Film& film, bool denoise, const std::string& device, bool showProgress, bool verbose,
                    RenderCounters& counters, DeviceReport& report);

} // namespace urbis
