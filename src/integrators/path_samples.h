// One pixel's path samples added to the film (host+device): the loop both backends run per pixel.
#pragma once

#include "film/film_view.h"
#include "integrators/integrator.h"

namespace urbis {

/// Adds path samples `samples` of pixel (px, py) to the film: the radiance sum goes on from the
/// stored one in sample order, so any split of 0..n-1 into calls gives the same bits; so does the
/// sum of squared luminance where the film keeps AOVs (the denoiser's per-pixel variance). Returns
/// the rays traced.
URBIS_HD inline uint32_t addPathSamples(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                        uint32_t px, uint32_t py, SampleRange samples, const FilmView& film) {
    const size_t pixel = film.pixel(px, py);
    Vec3f sum = film.radianceSum[pixel];
    float squares = film.luminanceSqSum ? film.luminanceSqSum[pixel] : 0.0f;
    uint32_t rays = 0;
    for (uint32_t s = samples.first; s < samples.first + samples.count; ++s) {
        const PathSample sample = integrateSample(scene, camera, settings, px, py, s);
        sum += sample.radiance;
        const float l = luminance(sample.radiance);
        squares += l * l;
        rays += sample.rays;
    }
    film.radianceSum[pixel] = sum;
    if (film.luminanceSqSum) film.luminanceSqSum[pixel] = squares;
    film.sampleCount[pixel] += samples.count;
    return rays;
}

} // namespace urbis
