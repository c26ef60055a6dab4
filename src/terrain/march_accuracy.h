// The Cambridge work's correctness measures of a terrain march against a reference march over the
// same rays: missed intersections, height-difference error (HDE), intersection-distance error (IDE).
#pragma once

#include "math/ray.h"
#include "scene/terrain_record.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace urbis {

/// Hits whose distance from the camera lies in [from, to) metres, and their height-difference error.
struct HdeBand {
    double from = 0, to = 0;          ///< metres from the ray's origin
    size_t hits = 0;
    double meanHde = 0, maxHde = 0;   ///< metres
};

/// The bands HDE is reported in apart (the goal's "under 1 cm at 1 km" is the first): from the
/// camera to 1 km, 1-2 km, 2-4 km, and beyond 4 km to the horizon.
inline constexpr double kHdeBandEdges[] = {0.0, 1000.0, 2000.0, 4000.0, INFINITY};
inline constexpr size_t kHdeBands = std::size(kHdeBandEdges) - 1;

/// What one march does against the reference over the same camera rays.
struct MarchAccuracy {
    size_t hits = 0;                 ///< rays it hits the terrain with
    size_t missed = 0;               ///< rays the reference hits that it misses, or hits over 1 m farther
    size_t extra = 0;                ///< rays it hits over 1 m nearer than the reference, or that the reference misses
    double meanHde = 0, maxHde = 0;  ///< |ray height - terrain height| at its hits, metres
    double meanIde = 0, maxIde = 0;  ///< |its distance - the reference's|, metres, over rays both hit
    std::array<HdeBand, kHdeBands> byDistance;  ///< the HDE of its hits by their distance (kHdeBandEdges)
};

/// The accuracy of hit distances `t` (negative: no hit) against `reference`, for `rays` over
/// `terrain` (samples `data`).
MarchAccuracy marchAccuracy(const TerrainRecord& terrain, const float* data, const std::vector<Ray>& rays,
                            const std::vector<float>& t, const std::vector<float>& reference);

} // namespace urbis
