// `urbis bench --terrain-accuracy`: the terrain's marches measured against the fixed-step reference,
// after the Cambridge work's correctness measures (height-difference error, intersection-distance
// error, missed intersections), with each march's time, on the CPU or the GPU.
#pragma once

#include "app/bench_command.h"
#include "terrain/march_accuracy.h"

#include <string>

namespace urbis {

/// Runs the measurement of `o`'s terrain (an fBm landscape unless --terrain or --dem says otherwise)
/// over its film's size from its camera (default: 120 m above the ground a fifth into the terrain,
/// looking 1 km across it), prints a table and writes --json.
void runTerrainAccuracy(const BenchOptions& o, bool onGpu, const std::string& deviceName, int repeats);

} // namespace urbis
