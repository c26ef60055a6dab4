#include "film/film_output.h"

#include "film/exr_file.h"
#include "model/input_error.h"

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

bool filmOutputNeedsAovs(const std::string& path) { return filmFormatOf(path) == FilmFormat::Exr; }

void writeFilm(const Film& film, const std::string& path, const FilmOutputOptions& options) {
    switch (filmFormatOf(path)) {
    case FilmFormat::Png: return writePng(toneMap(meanRadiance(film), options.exposureEv), path);
    case FilmFormat::Exr: return writeExr(film, path, ExrOptions{std::exp2(options.exposureEv), options.exrFloat});
    }
}

size_t hostFilmBytes(uint32_t width, uint32_t height, bool withAovs) {
    // PNG: the mean radiance, its 8-bit copy and libpng's row (its own state is a few KiB).
    const size_t png = size_t(width) * height * (sizeof(Vec3f) + 3) + size_t(width) * 3;
    return Film::bytesFor(width, height, withAovs) + std::max(png, withAovs ? exrWriteBytes(width, height) : size_t(0));
}

} // namespace urbis
