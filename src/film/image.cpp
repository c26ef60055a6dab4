#include "film/image.h"

#include "io/atomic_file.h"
#include "base/input_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <png.h>

namespace urbis {

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
    // zlib level 3 rather than libpng's 6: a 1080p render at 4 spp in 200 ms rather than 586 ms, for a
    // file 4 % larger (the encoder is a large part of a sequence's host time per frame).
    png_set_compression_level(png, 3);
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
    writeThroughTemporary(path, [&](const std::string& temporary) -> std::string {
        FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) return std::string("cannot write: ") + std::strerror(errno);
        const bool encoded = encodePng(image, file);
        const bool closed = std::fclose(file) == 0;
        return encoded && closed ? "" : "failed to write PNG data";
    });
}

} // namespace urbis
