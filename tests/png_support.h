// Reading a PNG's pixels back in tests (libpng's simplified API): files compared by what they show,
// not by their compressed bytes.
#pragma once

#include <png.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace urbis::test {

/// A PNG's pixels as 8-bit RGB, row-major; empty if it cannot be read.
struct Rgb {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> pixels;
};

inline Rgb readRgbPng(const std::filesystem::path& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) return {};
    image.format = PNG_FORMAT_RGB;
    Rgb out{image.width, image.height, std::vector<uint8_t>(PNG_IMAGE_SIZE(image))};
    if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) return {};
    return out;
}

} // namespace urbis::test
