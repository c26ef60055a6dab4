// The accumulating HDR film (host): per pixel the running sum of radiance and the sample count,
// and, when asked for, the AOVs. Render calls add samples to it; files are written from it.
#pragma once

#include "film/film_view.h"
#include "film/image.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace urbis {

template <class T>
using HostArray = std::vector<T>;

/// A film's per-pixel arrays: `Array` is HostArray on the host and DeviceBuffer on the GPU, so
/// that both hold the same members. The AOV arrays are empty when the film keeps no AOVs.
template <template <class> class Array>
struct FilmArrays {
    Array<Vec3f> radianceSum;
    Array<uint32_t> sampleCount;
    Array<Vec3f> albedoSum, normalSum, positionSum;
    Array<float> depthSum;
    Array<uint32_t> surfaceCount, objectId, partId;
    Array<Vec3f> emissionSum;
    Array<float> luminanceSqSum;
};

/// Calls `f(viewMember, isAov, array...)` for every per-pixel array, `array...` being that member
/// of each of `arrays`: the one list that film views, device copies and memory accounting follow.
template <class F, class... Arrays>
void forEachFilmArray(F&& f, Arrays&... arrays) {
    f(&FilmView::radianceSum, false, arrays.radianceSum...);
    f(&FilmView::sampleCount, false, arrays.sampleCount...);
    f(&FilmView::albedoSum, true, arrays.albedoSum...);
    f(&FilmView::normalSum, true, arrays.normalSum...);
    f(&FilmView::positionSum, true, arrays.positionSum...);
    f(&FilmView::depthSum, true, arrays.depthSum...);
    f(&FilmView::surfaceCount, true, arrays.surfaceCount...);
    f(&FilmView::objectId, true, arrays.objectId...);
    f(&FilmView::partId, true, arrays.partId...);
    f(&FilmView::emissionSum, true, arrays.emissionSum...);
    f(&FilmView::luminanceSqSum, true, arrays.luminanceSqSum...);
}

/// The value a fresh film's array starts from: ids kSkyId (no surface seen yet), all else zero.
template <class T>
T emptyFilmValue(T* FilmView::*member) {
    if constexpr (std::is_same_v<T, uint32_t>)
        if (member == &FilmView::objectId || member == &FilmView::partId) return kSkyId;
    return {};
}

/// A host film of `width` x `height` pixels.
struct Film {
    uint32_t width = 0, height = 0;
    FilmArrays<HostArray> arrays;

    Film() = default;
    /// An empty film: no samples; the AOV arrays only `withAovs`.
    Film(uint32_t width, uint32_t height, bool withAovs);

    size_t pixels() const { return size_t(width) * height; }
    bool hasAovs() const { return !arrays.albedoSum.empty(); }
    /// Samples per pixel so far (every render call adds the same samples to every pixel).
    uint32_t samplesTaken() const { return arrays.sampleCount.empty() ? 0 : arrays.sampleCount[0]; }
    /// The `count` samples after those taken: where `--spp` and progressive rendering go on from.
    SampleRange nextSamples(uint32_t count) const { return {samplesTaken(), count}; }
    /// Pointers into this film's arrays, for the CPU backend.
    FilmView view();
    /// Host bytes of the arrays of such a film.
    static size_t bytesFor(uint32_t width, uint32_t height, bool withAovs);
};

/// Mean radiance of pixel `pixel`: its sum over its sample count (black where none was added).
/// Divides as Vec3f does, so that a film's mean is bit for bit the mean the renderers computed
/// before they kept a film.
Vec3f meanRadiance(const Film& film, size_t pixel);

/// Mean radiance of every pixel.
LinearImage meanRadiance(const Film& film);

/// A film's AOVs resolved per pixel (docs/film.md defines each).
struct AovImages {
    std::vector<Vec3f> albedo, normal;   ///< means over every sample (the sky counts as zero)
    std::vector<Vec3f> position;         ///< mean over the samples that hit a surface; zero if none
    std::vector<float> depth;            ///< mean over the samples that hit a surface; +inf if none
    std::vector<uint32_t> object, part;  ///< through the pixel centre; kSkyId for the sky
    std::vector<uint32_t> samples;       ///< samples added to the pixel
};

/// The per-pixel AOVs of a film that keeps them (hasAovs()).
AovImages resolveAovs(const Film& film);

} // namespace urbis
