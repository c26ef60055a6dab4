// `urbis render --frames`: the frames of the scene's animation from one scene build, each with the
// camera and the time of day of its instant, written to a temporary and renamed, frames whose files
// exist kept (unless --overwrite), a progress line a frame, then --video (docs/animation.md).
#pragma once

#include "app/render_command.h"

#include <vector>

namespace urbis {

/// Throws a usage InputError before any work where the frames cannot be rendered as asked: a scene
/// without keyframes, a --frames range that does not parse or reaches past the last frame, an --out
/// without one frame field (%04d), --stats (a still's), or a --video that cannot be made. Creates
/// the frames' folder.
void checkFrameOptions(const RenderOptions& options);

/// Renders the frames of `options.frames` still to render over `prepared` (built from options.scene),
/// relighting it for each frame's time of day where the animation moves it, then encodes --video.
/// Frame N's image is the same whether rendered alone or in any sequence. The scene is uploaded to a
/// GPU once for the whole sequence; a frame whose time of day moves uploads again only its lights
/// (RenderBackend::relight). With several `gpus` (--devices) each renders whole frames, taken from one
/// queue by a host thread a device. Under mpirun (`world` with several ranks) each rank renders its
/// share of the frames (cluster/frame_spread.h), on the GPU of its local rank with --device cuda, and
/// rank 0 encodes --video once every rank is done.
void renderFrames(const RenderOptions& options, PreparedScene& prepared, const std::vector<int>& gpus, const MpiWorld* world);

} // namespace urbis
