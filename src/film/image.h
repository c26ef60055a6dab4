// Host images: linear float radiance and 8-bit sRGB pixels, and the PNG writer.
#pragma once

#include "math/vec.h"

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

/// Writes a PNG atomically: to `path`.tmp, then renamed. Throws InputError naming the file on failure.
void writePng(const Rgb8Image& image, const std::string& path);

} // namespace urbis
