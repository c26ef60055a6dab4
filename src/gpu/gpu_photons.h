// The photon passes on one GPU (gpu_photons.cu), as PhotonPasses: per sample index the photons traced
// from the lights, then the hash grid (a stable sort of the photons by bucket: deterministic) or the
// photon buffers (visibility flags, memory for the blocks first seen, fixed-point splats), before the
// sample's camera pass. The buffers persist between calls, as the CPU's do (cpu/cpu_photons.h).
#pragma once

#include "gpu/gpu_backend.h"
#include "integrators/photon_passes.h"
#include "scene/scene.h"

#include <memory>

namespace urbis {

class GpuPhotonPasses final : public PhotonPasses {
public:
    /// The passes of the host `scene` on the device `gpu` uploaded it to (which must outlive this).
    GpuPhotonPasses(const Scene& scene, const GpuScene& gpu);
    ~GpuPhotonPasses() override;
    GpuPhotonPasses(const GpuPhotonPasses&) = delete;
    GpuPhotonPasses& operator=(const GpuPhotonPasses&) = delete;

    PhotonsView runPass(const Camera& camera, const RenderSettings& settings, uint32_t sample, PhotonTimings& timings) override;
    double timeLightingPass(const PhotonsView& photons, const Camera& camera, const RenderSettings& settings,
                            uint32_t sample) override;
    size_t bytes() const override;

private:
    struct Impl;
    const Scene& scene_;
    const GpuScene& gpu_;
    std::unique_ptr<Impl> impl_;
};

} // namespace urbis
