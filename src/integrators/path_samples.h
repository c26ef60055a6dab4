// One pixel's path samples added to the film (host+device): the loop both backends run per pixel.
#pragma once

#include "film/film_view.h"
#include "integrators/integrator.h"

namespace urbis {

/// Adds path samples `samples` of pixel (px, py) to the film: the radiance sum goes on from the
/// stored one in sample order, so any split of 0..n-1 into calls gives the same bits. Returns the
/// rays traced.
URBIS_HD inline uint32_t addPathSamples(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                        uint32_t px, uint32_t py, SampleRange samples, const FilmView& film) {
    const size_t pixel = film.pixel(px, py);
    Vec3f sum = film.radianceSum[pixel];
    uint32_t rays = 0;
    for (uint32_t s = samples.first; s < samples.first + samples.count; ++s) {
        const PathSample sample = integrateSample(scene, camera, settings, px, py, s);
        sum += sample.radiance;
        rays += sample.rays;
    }
    film.radianceSum[pixel] = sum;
    film.sampleCount[pixel] += samples.count;
    return rays;
}

} // namespace urbis
