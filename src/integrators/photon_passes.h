// The light pre-pass of the photon integrators (docs/photons.md) on one device, behind one interface
// that the CPU (cpu/cpu_photons.h) and each GPU (GpuScene::photonPasses) implement: per sample index
// the photons traced from the lights, then the hash grid built or the photon buffers splatted. What a
// pass leaves (the buffers) persists in the object, so that a resting camera accumulates and a moving
// one reuses them. Called once a pass, never per ray: a virtual call is cheap here.
#pragma once

#include "integrators/photon_timings.h"
#include "scene/camera.h"
#include "scene/photon_view.h"
#include "scene/render_settings.h"

#include <cstddef>
#include <cstdint>

namespace urbis {

class PhotonPasses {
public:
    virtual ~PhotonPasses() = default;
    /// Runs the photon pass of sample `sample` for settings.integrator (PhotonMap or PhotonBuffers) and
    /// returns what that sample's camera pass must see in SceneView::photons (valid until the next
    /// call); adds its times and counts to `timings` and sets its buffers' counts (texels, blocks).
    virtual PhotonsView runPass(const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                PhotonTimings& timings) = 0;
    /// One lighting pass apart (PhotonTimings::lightingPass) on `photons`, what runPass returned for
    /// sample `sample`: the camera chains' ends first, then, timed, the indirect light at each; seconds.
    virtual double timeLightingPass(const PhotonsView& photons, const Camera& camera, const RenderSettings& settings,
                                    uint32_t sample) = 0;
    /// Device (or host) bytes held: photons, grid, buffers.
    virtual size_t bytes() const = 0;
};

} // namespace urbis
