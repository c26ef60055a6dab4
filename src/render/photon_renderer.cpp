#include "render/photon_renderer.h"

namespace urbis {

PhotonsView PhotonRenderer::lightPass(size_t device, const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                      PhotonTimings& timings) {
    std::unique_ptr<PhotonPasses>& passes = passes_[device];
    if (!passes) passes = devices()[device]->photonPasses(scene());
    return passes->runPass(camera, settings, sample, timings);
}

std::optional<PhotonTimings> PhotonRenderer::reportPasses(const Camera& camera, const RenderSettings& settings,
                                                          uint32_t sample, const PhotonsView& last, PhotonTimings timings) {
    timings.lightingPass = passes_[0]->timeLightingPass(last, camera, settings, sample);
    return timings;
}

} // namespace urbis
