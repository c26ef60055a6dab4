// The photon integrators on the CPU (docs/photons.md): per sample index one photon pass (photons
// traced from the lights over TBB, then the hash grid built or the photon buffers splatted) and one
// camera pass (renderCpu). The photon buffers persist in a PhotonState across calls, so that a
// resting camera accumulates and a moving one reuses them (the paper's progressive and slow-motion frames).
#pragma once

#include "film/film.h"
#include "integrators/photon_blocks.h"
#include "integrators/photon_timings.h"
#include "integrators/render_counters.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

#include <vector>

namespace urbis {

/// What the photon integrators keep between calls on one scene: the blocks and their buffers.
struct PhotonState {
    bool built = false;
    PhotonBlockSet blocks;
    std::vector<unsigned long long> texels;   ///< 3 per texel
    uint32_t passes = 0;                      ///< photon passes splatted so far
    float fixedScale = 0;
    bool flagged = false;                     ///< whether the visibility flags were taken for flaggedCamera
    Camera flaggedCamera;
};

/// The photon map's hash grid of `photons` for gather radius `radius` (cells of side 2 r): a counting
/// sort by bucket, stable, so the order is that of the input. Fills `sorted`, `start`, `end` and the view.
PhotonGridView buildPhotonGridCpu(const std::vector<Photon>& photons, float radius, std::vector<Photon>& sorted,
                                  std::vector<uint32_t>& start, std::vector<uint32_t>& end);

/// Adds samples `samples` of every pixel to `film` by settings.integrator (PhotonMap or
/// PhotonBuffers), one photon pass per sample. The photon map's pass is the sample index (its radius
/// shrinks with it); the buffers' passes go on from `state.passes`.
void renderPhotonsCpu(const Scene& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                      Film& film, PhotonState& state, RenderCounters& counters, PhotonTimings& timings);

} // namespace urbis
