#include "film/aov_display.h"

#include "film/film_output.h"
#include "film/tone_map.h"
#include "math/hash.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace urbis {

namespace {

uint8_t unitByte(float v) { return uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

/// Blue (0) through green to red (1).
Vec3f heat(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    return {std::clamp(2.0f * t - 0.5f, 0.0f, 1.0f), 1.0f - std::abs(2.0f * t - 1.0f), std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f)};
}

/// The display colour (in [0, 1], already encoded) of pixel `i` of `film`'s layer `display`.
Vec3f pixelColour(const Film& film, FilmDisplay display, size_t i) {
    const FilmArrays<HostArray>& a = film.arrays;
    const float n = float(std::max(a.sampleCount[i], 1u));
    switch (display) {
    case FilmDisplay::Albedo: {
        const Vec3f albedo = a.albedoSum[i] / n;
        return {srgbEncode(std::clamp(albedo.x, 0.0f, 1.0f)), srgbEncode(std::clamp(albedo.y, 0.0f, 1.0f)),
                srgbEncode(std::clamp(albedo.z, 0.0f, 1.0f))};
    }
    case FilmDisplay::Normal: return a.normalSum[i] / n * 0.5f + Vec3f{0.5f, 0.5f, 0.5f};
    case FilmDisplay::Depth: {
        if (!a.surfaceCount[i]) return {};
        const float depth = a.depthSum[i] / float(a.surfaceCount[i]);
        const float v = 1.0f - std::log10(std::max(depth, 1.0f)) / 4.0f;
        return {v, v, v};
    }
    case FilmDisplay::Ids: {
        if (a.objectId[i] == kSkyId) return {};
        const uint32_t h = hash2(a.objectId[i], a.partId[i]);
        return {0.2f + 0.8f * float(h & 255) / 255.0f, 0.2f + 0.8f * float((h >> 8) & 255) / 255.0f,
                0.2f + 0.8f * float((h >> 16) & 255) / 255.0f};
    }
    case FilmDisplay::Error: {
        // The standard error of the mean over the mean, from the running sums of Y and Y^2.
        const float mean = luminance(a.radianceSum[i]) / n;
        const float meanSq = a.luminanceSqSum[i] / n;
        const float error = n > 1 ? std::sqrt(std::max(meanSq - mean * mean, 0.0f) / (n - 1)) : 0.0f;
        return heat(mean > 0 ? 2.0f * error / mean : 0.0f);
    }
    case FilmDisplay::Image: break;
    }
    return {};
}

} // namespace

Rgb8Image displayImage(const Film& film, FilmDisplay display, float exposureEv) {
    if (display == FilmDisplay::Image) return toneMap(film, exposureEv);
    if (!film.hasAovs()) throw std::invalid_argument("displayImage: the film keeps no AOVs to show");
    Rgb8Image out{film.width, film.height, std::vector<uint8_t>(film.pixels() * 3)};
    tbb::parallel_for(uint32_t(0), film.height, [&](uint32_t y) {
        for (size_t i = size_t(y) * film.width; i < size_t(y + 1) * film.width; ++i) {
            const Vec3f c = pixelColour(film, display, i);
            for (int k = 0; k < 3; ++k) out.rgb[3 * i + k] = unitByte(c[k]);
        }
    });
    return out;
}

} // namespace urbis
