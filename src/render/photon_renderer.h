// The photon integrators' Renderer (docs/photons.md): the photon map (hash grid, progressive radius)
// and the photon buffers (Argudo et al.) share it. Each sample is a round: the light pass traces that
// sample's photons on every device (PhotonPasses), then the camera pass looks them up. The passes
// and the buffers they fill persist between calls, per device, until the lights change.
#pragma once

#include "render/renderer.h"

namespace urbis {

class PhotonRenderer final : public Renderer {
public:
    PhotonRenderer(const Scene& scene, const RendererOptions& options) : Renderer(scene, options) { forgetState(); }

private:
    bool hasLightPass() const override { return true; }
    PhotonsView lightPass(size_t device, const Camera& camera, const RenderSettings& settings, uint32_t sample,
                          PhotonTimings& timings) override;
    std::optional<PhotonTimings> reportPasses(const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                              const PhotonsView& last, PhotonTimings timings) override;
    /// One empty slot a device: the slots exist before the devices' threads fill them.
    void forgetState() override {
        passes_.clear();
        passes_.resize(devices().size());
    }
    size_t stateBytes() const override { return passes_.empty() || !passes_[0] ? 0 : passes_[0]->bytes(); }

    std::vector<std::unique_ptr<PhotonPasses>> passes_;   ///< by device, each made on its first pass
};

} // namespace urbis
