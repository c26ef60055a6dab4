// Host images: a linear float film and 8-bit sRGB pixels.
#pragma once

#include "math/vec.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace urbis {

/// Linear radiance per pixel, row-major from the top-left.
struct LinearImage {
    uint32_t width = 0, height = 0;
    std::vector<Vec3f> pixels;
};

/// 8-bit sRGB RGB pixels, row-major from the top-left.
struct Rgb8Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb;
};

/// Host bytes of a `width` x `height` frame from render to file: the linear film, its tone-mapped
/// 8-bit copy and the PNG encoder's row (libpng streams rows; its own state is a few KiB).
inline size_t hostFilmBytes(uint32_t width, uint32_t height) {
    const size_t pixels = size_t(width) * height;
    return pixels * (sizeof(Vec3f) + 3) + size_t(width) * 3;
}

/// Tone maps a linear image with exposure `exposureEv` (stops) through the filmic curve to sRGB.
Rgb8Image toneMap(const LinearImage& image, float exposureEv);

/// Writes a PNG atomically: to `path`.tmp, then renamed. Throws InputError naming the file on failure.
void writePng(const Rgb8Image& image, const std::string& path);

} // namespace urbis
