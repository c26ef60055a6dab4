// One pixel of the viewer's picture (host+device): what each FilmDisplay layer shows and how its
// values become 8-bit sRGB. The CPU's displayImage (film/aov_display.h) and the GPU's picture
// kernel (GpuScene::drawPicture) both call it, so the picture is made where the film is.
#pragma once

#include "film/film_view.h"
#include "film/tone_map.h"
#include "math/hash.h"

#include <cmath>
#include <cstdint>

namespace urbis {

/// What the viewer shows of the film.
enum class FilmDisplay : uint8_t {
    Image,     ///< the tone-mapped radiance
    Albedo,    ///< mean albedo, sRGB-encoded
    Normal,    ///< mean shading normal, each axis from [-1, 1] to [0, 1]
    Depth,     ///< z depth on a log scale: 1 m white to 10 km black; the sky black
    Ids,       ///< a colour hashed from each pixel's object and part; the sky black
    Error,     ///< heat map of the relative standard error of the pixel's mean luminance: blue 0 to red 50 %
};

namespace display_detail {

URBIS_HD inline uint8_t unitByte(float v) { return uint8_t(fminf(fmaxf(v, 0.0f), 1.0f) * 255.0f + 0.5f); }

/// Blue (0) through green to red (1).
URBIS_HD inline Vec3f heat(float t) {
    t = fminf(fmaxf(t, 0.0f), 1.0f);
    return {fminf(fmaxf(2.0f * t - 0.5f, 0.0f), 1.0f), 1.0f - fabsf(2.0f * t - 1.0f), fminf(fmaxf(1.0f - 2.0f * t, 0.0f), 1.0f)};
}

URBIS_HD inline float srgbUnit(float v) { return srgbEncode(fminf(fmaxf(v, 0.0f), 1.0f)); }

/// The display colour (in [0, 1], already encoded) of pixel `i` of a layer other than Image.
URBIS_HD inline Vec3f layerColour(const FilmView& film, FilmDisplay display, size_t i) {
    const float n = float(film.sampleCount[i] > 1u ? film.sampleCount[i] : 1u);
    switch (display) {
    case FilmDisplay::Albedo: {
        const Vec3f albedo = film.albedoSum[i] / n;
        return {srgbUnit(albedo.x), srgbUnit(albedo.y), srgbUnit(albedo.z)};
    }
    case FilmDisplay::Normal: return film.normalSum[i] / n * 0.5f + Vec3f{0.5f, 0.5f, 0.5f};
    case FilmDisplay::Depth: {
        if (!film.surfaceCount[i]) return {};
        const float depth = film.depthSum[i] / float(film.surfaceCount[i]);
        const float v = 1.0f - log10f(fmaxf(depth, 1.0f)) / 4.0f;
        return {v, v, v};
    }
    case FilmDisplay::Ids: {
        if (film.objectId[i] == kSkyId) return {};
        const uint32_t h = hash2(film.objectId[i], film.partId[i]);
        return {0.2f + 0.8f * float(h & 255) / 255.0f, 0.2f + 0.8f * float((h >> 8) & 255) / 255.0f,
                0.2f + 0.8f * float((h >> 16) & 255) / 255.0f};
    }
    case FilmDisplay::Error: {
        // The standard error of the mean over the mean, from the running sums of Y and Y^2.
        const float mean = luminance(film.radianceSum[i]) / n;
        const float meanSq = film.luminanceSqSum[i] / n;
        const float error = n > 1 ? sqrtf(fmaxf(meanSq - mean * mean, 0.0f) / (n - 1)) : 0.0f;
        return heat(mean > 0 ? 2.0f * error / mean : 0.0f);
    }
    case FilmDisplay::Image: break;
    }
    return {};
}

} // namespace display_detail

/// Writes pixel `i` of `film`'s layer `display` as three bytes of sRGB at `rgb`: Image tone mapped
/// (toneMapChannel, 2^exposure = `exposureScale`) from the mean radiance, as a PNG of the film has
/// it; any other layer needs a film with AOVs.
URBIS_HD inline void displayPixel(const FilmView& film, FilmDisplay display, float exposureScale, size_t i, uint8_t* rgb) {
    if (display == FilmDisplay::Image) {
        const uint32_t count = film.sampleCount[i];
        const Vec3f mean = count ? film.radianceSum[i] / float(count) : Vec3f{};
        for (int c = 0; c < 3; ++c) rgb[c] = toneMapChannel(mean[c], exposureScale);
        return;
    }
    const Vec3f colour = display_detail::layerColour(film, display, i);
    for (int c = 0; c < 3; ++c) rgb[c] = display_detail::unitByte(colour[c]);
}

} // namespace urbis
