// Which frames of an animation to render: the --frames range, the file name of each frame, and the
// frames whose files are still missing (a sequence resumes where it stopped). Small and free of the
// render itself, so that frames can be dealt out elsewhere (across MPI ranks) with the same rules.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace urbis {

/// Frames first..last, both included.
struct FrameRange {
    uint32_t first = 0, last = 0;
    uint32_t count() const { return last - first + 1; }
};

/// Reads --frames: "A:B" (A <= B), "A" (that frame alone) or "A:" (A to the last of `frameCount`
/// frames); nothing with `error` set where the text is none of these or reaches past frame
/// frameCount - 1 ("frame 130 is past the last frame, 119").
std::optional<FrameRange> parseFrameRange(std::string_view text, uint32_t frameCount, std::string& error);

/// Whether `pattern` names one file per frame: exactly one printf field %d or %0Nd (N 1..9) and no
/// other % but %%; `error` says what is wrong otherwise.
bool isFramePattern(std::string_view pattern, std::string& error);

/// The file of `frame` under `pattern` (isFramePattern): frames/f%04d.png and 7 give frames/f0007.png.
std::string framePath(std::string_view pattern, uint32_t frame);

/// The frames of `range` still to render, in order: all with `overwrite`, else those whose file under
/// `pattern` does not exist (each frame is written to a temporary and renamed, so an existing file is
/// a whole frame).
std::vector<uint32_t> framesToRender(const FrameRange& range, std::string_view pattern, bool overwrite);

} // namespace urbis
