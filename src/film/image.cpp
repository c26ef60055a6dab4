#include "film/image.h"

#include "film/tone_map.h"
#include "io/atomic_file.h"
#include "base/input_error.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <png.h>

namespace urbis {

Rgb8Image toneMap(const LinearImage& image, float exposureEv) {
    Rgb8Image out{image.width, image.height, std::vector<uint8_t>(size_t(image.width) * image.height * 3)};
    float scale = std::exp2(exposureEv);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = toneMapChannel(image.pixels[i][c], scale);
    return out;
}

namespace {

/// Encodes to an open file; returns false on any libpng error.
bool encodePng(const Rgb8Image& image, FILE* file) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (uint32_t y = 0; y < image.height; ++y)
        png_write_row(png, image.rgb.data() + size_t(y) * image.width * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

} // namespace

void writePng(const Rgb8Image& image, const std::string& path) {
    std::string temporary = path + ".tmp";
    FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw InputError(path + ": cannot write: " + std::strerror(errno), FailureKind::Output);
    bool encoded = encodePng(image, file);
    bool closed = std::fclose(file) == 0;
    std::error_code ec;
    if (!encoded || !closed) {
        std::filesystem::remove(temporary, ec);
        throw InputError(path + ": failed to write PNG data", FailureKind::Output);
    }
    commitTemporary(temporary, path);
}

} // namespace urbis
