#include "animation/frame_range.h"

#include <charconv>
#include <filesystem>

namespace urbis {

namespace {

/// The frame number `text` is, wholly; nothing for an empty text, a sign or anything after the digits.
std::optional<uint32_t> frameNumber(std::string_view text) {
    uint32_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return n;
}

/// `text` in single quotes, as messages quote what was given.
std::string quoted(std::string_view text) {
    std::string q(1, '\'');
    q += text;
    q += '\'';
    return q;
}

/// Where the one frame field of `pattern` starts and ends (the field "%04d" as [start, end)).
struct Field {
    size_t start = 0, end = 0;
    int width = 0;
};

std::optional<Field> fieldOf(std::string_view pattern, std::string& error) {
    std::optional<Field> found;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        Field f{i, i + 1, 0};
        if (f.end < pattern.size() && pattern[f.end] == '0') {
            ++f.end;
            if (f.end < pattern.size() && pattern[f.end] >= '1' && pattern[f.end] <= '9') f.width = pattern[f.end++] - '0';
        }
        if (f.end >= pattern.size() || pattern[f.end] != 'd' || (pattern[i + 1] == '0' && f.width == 0)) {
            error = quoted(pattern) + ": a frame field is %d or %0Nd (N 1..9)";
            return std::nullopt;
        }
        ++f.end;
        if (found) {
            error = quoted(pattern) + ": has more than one frame field (%d)";
            return std::nullopt;
        }
        found = f;
        i = f.end - 1;
    }
    if (!found) error = quoted(pattern) + ": needs a frame field, %d or %0Nd (frames/f%04d.png)";
    return found;
}

/// `text` with each %% as %.
std::string unescaped(std::string_view text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '%' && i + 1 < text.size() && text[i + 1] == '%') ++i;
    }
    return out;
}

} // namespace

std::optional<FrameRange> parseFrameRange(std::string_view text, uint32_t frameCount, std::string& error) {
    const size_t colon = text.find(':');
    const std::optional<uint32_t> first = frameNumber(text.substr(0, colon));
    std::optional<uint32_t> last = first;
    if (colon != std::string_view::npos)
        last = colon + 1 == text.size() && frameCount > 0 ? std::optional<uint32_t>(frameCount - 1) : frameNumber(text.substr(colon + 1));
    if (!first || !last) {
        error = quoted(text) + ": expected A:B, A or A: (frame numbers from 0)";
        return std::nullopt;
    }
    if (*first > *last) {
        error = quoted(text) + ": the first frame is after the last";
        return std::nullopt;
    }
    if (*last >= frameCount) {
        error = "frame " + std::to_string(*last) + " is past the animation's last frame, " + std::to_string(frameCount - 1);
        return std::nullopt;
    }
    return FrameRange{*first, *last};
}

bool isFramePattern(std::string_view pattern, std::string& error) { return fieldOf(pattern, error).has_value(); }

std::string framePath(std::string_view pattern, uint32_t frame) {
    std::string error;
    const Field f = fieldOf(pattern, error).value_or(Field{pattern.size(), pattern.size(), 0});
    std::string number = std::to_string(frame);
    if (number.size() < size_t(f.width)) number.insert(0, size_t(f.width) - number.size(), '0');
    return unescaped(pattern.substr(0, f.start)) + number + unescaped(pattern.substr(f.end));
}

std::vector<uint32_t> framesToRender(const FrameRange& range, std::string_view pattern, bool overwrite) {
    std::vector<uint32_t> frames;
    for (uint32_t n = range.first;; ++n) {
        std::error_code ec;
        if (overwrite || !std::filesystem::exists(framePath(pattern, n), ec)) frames.push_back(n);
        if (n == range.last) break;
    }
    return frames;
}

} // namespace urbis
