// The CPU backend: 16x16 tiles over TBB's thread pool, each pixel's samples summed in order,
// so the image is the same for any thread count.
#pragma once

#include "film/image.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene_view.h"

#include <cstdint>

namespace urbis {

struct RenderCounters {
    uint64_t rays = 0;
    double seconds = 0;
};

/// Path traces every pixel with settings.spp samples; the mean radiance per pixel.
/// With `showProgress`, draws a progress bar on stderr.
LinearImage renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                      bool showProgress, RenderCounters& counters);

/// The ID AOV: primaryHitId of every pixel, row by row (width x height).
std::vector<uint32_t> renderIdsCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings);

} // namespace urbis
