// --video: a sequence's frames encoded into one video by ffmpeg (Debian's `ffmpeg`, optional: a
// clear message where it is absent), written to a temporary and renamed.
#pragma once

#include "animation/frame_range.h"

#include <string>

namespace urbis {

/// Throws a usage InputError before any work where --video `path` cannot be made: an extension other
/// than .mp4 or .gif, frames that are not .png (`framePattern`), or no ffmpeg on the PATH.
void checkVideoOutput(const std::string& path, const std::string& framePattern);

/// Encodes the frames `range` of `framePattern` at `fps` into `path` (H.264 in .mp4, or a .gif with a
/// palette made from the frames) through a temporary. Throws an output InputError naming `path` when
/// ffmpeg fails.
void encodeVideo(const std::string& framePattern, const FrameRange& range, float fps, const std::string& path);

} // namespace urbis
