// The CPU backend: 16x16 tiles over TBB's thread pool adding to a film, each pixel's samples in
// order, so the film is the same for any thread count.
#pragma once

#include "film/film.h"
#include "film/pixel_rect.h"
#include "integrators/render_counters.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene_view.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Adds samples `samples` of every pixel to `film` (settings.width x settings.height): the path
/// tracer's radiance, and the AOV pass's when the film keeps AOVs. With `showProgress`, draws a
/// progress bar on stderr.
void renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
               Film& film, bool showProgress, RenderCounters& counters);

/// Adds samples `samples` of the pixels in `rect` only, as renderCpu does for every pixel: the bits of
/// those pixels are the same whichever rectangles a film is rendered in (the tiles of an MPI render).
void renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
               const PixelRect& rect, Film& film, RenderCounters& counters);

/// The mean radiance of a fresh film of settings.spp samples per pixel.
LinearImage renderCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                      bool showProgress, RenderCounters& counters);

/// The ID AOV: primaryHitId of every pixel, row by row (width x height).
std::vector<uint32_t> renderIdsCpu(const SceneView& scene, const Camera& camera, const RenderSettings& settings);

} // namespace urbis
