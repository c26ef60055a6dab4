#include "film/film_output.h"

#include "film/aov_display.h"
#include "film/denoise_filter.h"
#include "film/exr_file.h"
#include "film/tone_map.h"
#include "base/input_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace urbis {

FilmFormat filmFormatOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png") return FilmFormat::Png;
    if (extension == ".exr") return FilmFormat::Exr;
    throw InputError(path + ": cannot write '" + extension + "' images (the format follows the extension: .png, .exr)",
                     FailureKind::Usage);
}

bool filmOutputNeedsAovs(const std::string& path, uint32_t exrLayers) {
    return filmFormatOf(path) == FilmFormat::Exr && exrLayers != 0;
}

Rgb8Image toneMap(const Film& film, float exposureEv) { return displayImage(film, FilmDisplay::Image, exposureEv); }

void writeFilm(const Film& film, const std::string& path, const FilmOutputOptions& options) {
    switch (filmFormatOf(path)) {
    case FilmFormat::Png: return writePng(toneMap(film, options.exposureEv), path);
    case FilmFormat::Exr: return writeExr(film, path, ExrOptions{std::exp2(options.exposureEv), options.exrFloat, options.exrLayers});
    }
}

size_t hostFilmBytes(uint32_t width, uint32_t height, bool withAovs, bool denoise) {
    // PNG: the 8-bit image and libpng's row (its own state is a few KiB).
    const size_t png = size_t(width) * height * 3 + size_t(width) * 3;
    // The denoiser's buffers are freed before the file is written.
    const size_t beside = std::max({png, withAovs ? exrWriteBytes(width, height) : size_t(0),
                                    denoise ? size_t(width) * height * kDenoiseBytesPerPixel : size_t(0)});
    return Film::bytesFor(width, height, withAovs || denoise) + beside;
}

} // namespace urbis
