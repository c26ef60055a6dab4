// `urbis bench --terrain-accuracy`: the terrain's marches measured against the fixed-step reference,
// after the Cambridge work's correctness measures (height-difference error, intersection-distance
// error, missed intersections), with each march's time, on the CPU or the GPU.
#pragma once

#include "app/bench_command.h"

#include <string>

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

/// Runs the measurement of `o`'s terrain (an fBm landscape unless --terrain or --dem says otherwise)
/// over its film's size from its camera (default: 120 m above the ground a fifth into the terrain,
/// looking 1 km across it), prints a table and writes --json.
void runTerrainAccuracy(const BenchOptions& o, bool onGpu, const std::string& deviceName, int repeats);

} // namespace urbis
