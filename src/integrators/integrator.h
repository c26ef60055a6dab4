// The integrator interface both backends drive (host+device): one entry point per camera sample,
// dispatching on RenderSettings::integrator over the kinds of scene/integrator_choice.h.
#pragma once

#include "integrators/path_tracer.h"
#include "integrators/photon_camera.h"

namespace urbis {

/// Radiance of sample `sampleIndex` through pixel (px, py) by the integrator the settings name;
/// a pure function of its arguments.
URBIS_HD inline PathSample integrateSample(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                           uint32_t px, uint32_t py, uint32_t sampleIndex) {
    switch (settings.integrator) {
    case IntegratorKind::Path:
        return tracePath(scene, camera, settings, px, py, sampleIndex);
    case IntegratorKind::PhotonBuffers:
    case IntegratorKind::PhotonMap:
        return photonCameraSample(scene, camera, settings, px, py, sampleIndex);
    }
    return {};
}

} // namespace urbis
