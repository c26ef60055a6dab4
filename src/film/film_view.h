// The film as per-ray code sees it (host+device POD): pointers into the per-pixel arrays of a host
// Film or of its device copy, and the additions one pixel's samples make to them.
#pragma once

#include "math/vec.h"

#include <cstddef>
#include <cstdint>

namespace urbis {

/// Object and part id of a pixel (AOV) where its camera ray escapes to the sky.
inline constexpr uint32_t kSkyId = 0xffffffffu;

/// The samples of every pixel that one render call adds: `first` .. `first + count - 1`. Sample
/// indices seed the random numbers, so adding 0..7 and then 8..15 gives the film of 0..15.
struct SampleRange {
    uint32_t first = 0, count = 0;
};

/// What the AOV pass finds along the camera ray of one sample.
struct AovSample {
    bool surface = false;   ///< the ray hit a surface; otherwise only the zeros below count
    Vec3f albedo;           ///< the surface material's albedo
    Vec3f normal;           ///< unit shading normal, world space, facing the camera
    Vec3f emission;         ///< the surface material's emitted radiance
    Vec3f position;         ///< world position of the hit, metres
    float depth = 0;        ///< distance of the hit along the camera's view axis (z depth), metres
};

/// Pointers to a film's per-pixel arrays, row-major from the top-left. The AOV arrays are null when
/// the film keeps no AOVs.
struct FilmView {
    uint32_t width = 0, height = 0;
    Vec3f* radianceSum = nullptr;     ///< running sum of radiance, added in sample order
    uint32_t* sampleCount = nullptr;  ///< samples added to the pixel
    Vec3f* albedoSum = nullptr;       ///< over every sample (the sky adds zero)
    Vec3f* normalSum = nullptr;       ///< over every sample (the sky adds zero)
    Vec3f* positionSum = nullptr;     ///< over the samples that hit a surface
    float* depthSum = nullptr;        ///< over the samples that hit a surface
    uint32_t* surfaceCount = nullptr; ///< samples whose camera ray hit a surface
    uint32_t* objectId = nullptr;     ///< through the pixel's centre; kSkyId for the sky
    uint32_t* partId = nullptr;       ///< through the pixel's centre; kSkyId for the sky
    Vec3f* emissionSum = nullptr;     ///< over every sample: what the first surface emits (the sky adds zero)
    float* luminanceSqSum = nullptr;  ///< sum of squared radiance luminance, in sample order (the denoiser's variance)

    URBIS_HD bool hasAovs() const { return albedoSum != nullptr; }
    URBIS_HD size_t pixel(uint32_t x, uint32_t y) const { return size_t(y) * width + x; }
};

/// Adds one sample's AOVs to pixel `pixel`; call in sample order, as radiance is added.
URBIS_HD inline void addAovSample(const FilmView& film, size_t pixel, const AovSample& sample) {
    film.albedoSum[pixel] += sample.albedo;
    film.normalSum[pixel] += sample.normal;
    film.emissionSum[pixel] += sample.emission;
    if (!sample.surface) return;
    film.positionSum[pixel] += sample.position;
    film.depthSum[pixel] += sample.depth;
    film.surfaceCount[pixel] += 1;
}

} // namespace urbis
