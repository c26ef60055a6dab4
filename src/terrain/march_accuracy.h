// The Cambridge work's correctness measures of a terrain march against a reference march over the
// same rays: missed intersections, height-difference error (HDE), intersection-distance error (IDE).
#pragma once

#include "math/ray.h"
#include "scene/terrain_record.h"

#include <cstddef>
#include <vector>

namespace urbis {

/// What one march does against the reference over the same camera rays.
struct MarchAccuracy {
    size_t hits = 0;                 ///< rays it hits the terrain with
    size_t missed = 0;               ///< rays the reference hits that it misses, or hits over 1 m farther
    size_t extra = 0;                ///< rays it hits over 1 m nearer than the reference, or that the reference misses
    double meanHde = 0, maxHde = 0;  ///< |ray height - terrain height| at its hits, metres
    double meanIde = 0, maxIde = 0;  ///< |its distance - the reference's|, metres, over rays both hit
};

/// The accuracy of hit distances `t` (negative: no hit) against `reference`, for `rays` over
/// `terrain` (samples `data`).
MarchAccuracy marchAccuracy(const TerrainRecord& terrain, const float* data, const std::vector<Ray>& rays,
                            const std::vector<float>& t, const std::vector<float>& reference);

} // namespace urbis
