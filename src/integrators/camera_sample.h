// The camera ray a pixel sample starts from (host+device), shared by the path tracer's samples
// and the AOV pass, so that both see the same ray.
#pragma once

#include "math/rng.h"
#include "scene/camera.h"
#include "scene/render_settings.h"

namespace urbis {

/// The random numbers of sample `sampleIndex` of pixel (px, py).
URBIS_HD inline SampleStream pixelSampleStream(const RenderSettings& settings, uint32_t px, uint32_t py,
                                               uint32_t sampleIndex) {
    return SampleStream{settings.seed, py * settings.width + px, sampleIndex};
}

/// The camera ray through pixel (px, py) jittered by the next two numbers of `rng` (a fresh
/// pixelSampleStream: its dimensions 0 and 1), as tracePath starts its path.
URBIS_HD inline Ray cameraSampleRay(const Camera& camera, const RenderSettings& settings, uint32_t px, uint32_t py,
                                    SampleStream& rng) {
    const float jx = rng.draw(), jy = rng.draw();
    return camera.generateRay((float(px) + jx) / float(settings.width), (float(py) + jy) / float(settings.height));
}

} // namespace urbis
