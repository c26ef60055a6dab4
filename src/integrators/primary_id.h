// The ID AOV: which object and part the camera sees through a pixel's centre (host+device).
#pragma once

#include "geometry/scene_intersect.h"
#include "scene/camera.h"
#include "scene/render_settings.h"

namespace urbis {

/// ID of the sky (nothing hit).
inline constexpr uint32_t kSkyId = 0xffffffffu;

/// (object << kSurfacePartBits) | part of the first surface through the centre of pixel (px, py);
/// kSkyId where the ray escapes. The same for both representations of a wall.
URBIS_HD inline uint32_t primaryHitId(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                      uint32_t px, uint32_t py) {
    Ray ray = camera.generateRay((float(px) + 0.5f) / float(settings.width), (float(py) + 0.5f) / float(settings.height));
    SurfaceHit hit = intersectScene(scene, ray);
    if (!hit.valid()) return kSkyId;
    return (hit.object << kSurfacePartBits) | uint32_t(hit.part);
}

} // namespace urbis
