// Memory of the photon buffers (host): a block's level of detail by its distance from the camera
// (levels 0-4, the texel doubling per level, as Argudo et al.'s adaptive resolution) and its texels,
// given only to blocks the camera's chains reach (the visibility flags). docs/photons.md § Levels.
#pragma once

#include "scene/camera.h"
#include "scene/photon_view.h"
#include "scene/render_settings.h"

#include <cstdint>
#include <vector>

namespace urbis {

inline constexpr uint32_t kPhotonLevels = 5;

/// Level 0-4 of a block at `distance` metres from the camera: 0 nearer than `levelDistance`, one more
/// per doubling of the distance.
uint32_t photonBufferLevel(float distance, float levelDistance);

/// Sizes `block`'s layers for `level` (texel side `texel0` x 2^level, at most 4096 texels a side) and
/// places them at `texelOffset`, accumulating from pass `pass`.
void layOutPhotonBlock(PhotonBlock& block, uint32_t level, float texel0, uint32_t texelOffset, uint32_t pass);

/// Gives texels to every block flagged in `seen` that has none, at the level of its distance from
/// `eye`, after the `texelCount` texels already given; returns the new texel count.
uint32_t allocateSeenBlocks(std::vector<PhotonBlock>& blocks, const std::vector<uint8_t>& seen, Vec3f eye,
                            const RenderSettings& settings, uint32_t pass, uint32_t texelCount);

/// Whether the visibility flags must be taken (again) for `camera`: the first time, or when it is not
/// the camera `flaggedCamera` they were last taken for (then it becomes that camera). Once per view,
/// as the paper's flags once per frame: a camera at rest accumulates passes without a flag pass each.
bool newView(bool& flagged, Camera& flaggedCamera, const Camera& camera);

} // namespace urbis
