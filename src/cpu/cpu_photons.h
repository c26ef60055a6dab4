// The photon passes on the CPU (docs/photons.md), as PhotonPasses: per sample index the photons traced
// from the lights over TBB, then the hash grid built or the photon buffers splatted, before the sample's
// camera pass. The photon buffers persist in the object across calls, so that a resting camera
// accumulates and a moving one reuses them (the paper's progressive and slow-motion frames).
#pragma once

#include "integrators/photon_blocks.h"
#include "integrators/photon_passes.h"
#include "scene/scene.h"

#include <vector>

namespace urbis {

/// What the photon buffers keep between passes on one scene: the blocks and their buffers.
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

class CpuPhotonPasses final : public PhotonPasses {
public:
    /// The passes of `scene` (which must outlive this).
    explicit CpuPhotonPasses(const Scene& scene);

    /// The photon map's pass is the sample index (its radius shrinks with it); the buffers' passes go on
    /// from state().passes.
    PhotonsView runPass(const Camera& camera, const RenderSettings& settings, uint32_t sample, PhotonTimings& timings) override;
    double timeLightingPass(const PhotonsView& photons, const Camera& camera, const RenderSettings& settings,
                            uint32_t sample) override;
    size_t bytes() const override;

    /// The photon buffers as they are now.
    const PhotonState& state() const { return state_; }

private:
    const Scene& scene_;
    SceneView view_;          ///< the host scene with the lights' photon emission
    PhotonState state_;
    std::vector<Photon> slots_, stored_, sorted_;   ///< the photon map's pass: what its grid points into
    std::vector<uint32_t> start_, end_;
};

} // namespace urbis
