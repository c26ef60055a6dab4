#include "film/film.h"

#include <limits>
#include <stdexcept>

namespace urbis {

Film::Film(uint32_t filmWidth, uint32_t filmHeight, bool withAovs) : width(filmWidth), height(filmHeight) {
    forEachFilmArray(
        [&](auto member, bool isAov, auto& array) {
            if (!isAov || withAovs) array.assign(pixels(), emptyFilmValue(member));
        },
        arrays);
}

FilmView Film::view() {
    FilmView view{width, height};
    forEachFilmArray([&](auto member, bool, auto& array) { view.*member = array.empty() ? nullptr : array.data(); },
                     arrays);
    return view;
}

size_t Film::bytesFor(uint32_t width, uint32_t height, bool withAovs) {
    size_t perPixel = 0;
    FilmArrays<HostArray> none;
    forEachFilmArray(
        [&](auto, bool isAov, auto& array) {
            if (!isAov || withAovs) perPixel += sizeof(typename std::decay_t<decltype(array)>::value_type);
        },
        none);
    return perPixel * width * height;
}

namespace {
/// `sum` over `count`, zero for no samples.
Vec3f meanOf(Vec3f sum, uint32_t count) { return count ? sum / float(count) : Vec3f{}; }
} // namespace

Vec3f meanRadiance(const Film& film, size_t pixel) {
    return meanOf(film.arrays.radianceSum[pixel], film.arrays.sampleCount[pixel]);
}

LinearImage meanRadiance(const Film& film) {
    LinearImage image{film.width, film.height, std::vector<Vec3f>(film.pixels())};
    for (size_t i = 0; i < film.pixels(); ++i) image.pixels[i] = meanRadiance(film, i);
    return image;
}

AovImages resolveAovs(const Film& film) {
    if (!film.hasAovs()) throw std::invalid_argument("resolveAovs: the film keeps no AOVs");
    const FilmArrays<HostArray>& a = film.arrays;
    const size_t n = film.pixels();
    AovImages out{std::vector<Vec3f>(n), std::vector<Vec3f>(n), std::vector<Vec3f>(n), std::vector<float>(n),
                  a.objectId, a.partId, a.sampleCount};
    for (size_t i = 0; i < n; ++i) {
        out.albedo[i] = meanOf(a.albedoSum[i], a.sampleCount[i]);
        out.normal[i] = meanOf(a.normalSum[i], a.sampleCount[i]);
        out.position[i] = meanOf(a.positionSum[i], a.surfaceCount[i]);
        out.depth[i] = a.surfaceCount[i] ? a.depthSum[i] / float(a.surfaceCount[i]) : std::numeric_limits<float>::infinity();
    }
    return out;
}

} // namespace urbis
