// The photon passes on the GPU (gpu_photons.cu): per sample index the photons traced from the lights,
// then the hash grid (a stable sort of the photons by bucket: deterministic) or the photon buffers
// (visibility flags, memory for the blocks first seen, fixed-point splats), before the camera pass
// that GpuScene::renderPhotons launches. The buffers persist between calls, as PhotonState does on the CPU.
#pragma once

#include "integrators/photon_timings.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

#include <memory>

namespace urbis {

class GpuPhotonPasses {
public:
    GpuPhotonPasses();
    ~GpuPhotonPasses();
    GpuPhotonPasses(const GpuPhotonPasses&) = delete;
    GpuPhotonPasses& operator=(const GpuPhotonPasses&) = delete;

    /// Runs the photon pass of sample `sample` on the device scene `view` (of the host `scene`) and
    /// returns what the camera pass of that sample must see in SceneView::photons.
    PhotonsView runPass(const Scene& scene, const SceneView& view, const Camera& camera, const RenderSettings& settings,
                        uint32_t sample, PhotonTimings& timings);
    /// One lighting pass apart (PhotonTimings::lightingPass) on `photons`, what runPass returned for
    /// sample `sample`: the camera chains' ends first, then, timed, the indirect light at each; seconds.
    double timeLightingPass(const SceneView& view, const PhotonsView& photons, const Camera& camera,
                            const RenderSettings& settings, uint32_t sample);
    /// Device bytes it holds (photons, grid, buffers).
    size_t bytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace urbis
