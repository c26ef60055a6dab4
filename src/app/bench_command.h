// `urbis bench`: rays per second of primary, diffuse and shadow rays, and the time of a path-traced frame.
#pragma once

#include "app/render_command.h"

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct BenchOptions {
    RenderOptions render;       ///< city, camera, sun; the film's width and height are the batches' and the frame's
    std::string jsonFile;
    int repeats = 0;            ///< timed runs per measurement; 0: 20 on the GPU, 3 on the CPU
    int warmup = 3;             ///< untimed runs before them (GPU)
    bool terrainAccuracy = false;   ///< --terrain-accuracy: the terrain's marches against the reference (app/terrain_accuracy.h)
};

/// The scene bench measures without a scene file: 1920x1080 at 1 spp, 100,000 buildings.
SceneDescription benchDefaultScene();

/// The command line of `urbis bench`, resolved into BenchOptions once parsed.
struct BenchCommandLine {
    SceneCommandLine scene{benchDefaultScene()};
    BenchOptions options;
    BenchOptions resolve() const;
};

/// Registers the subcommand's options on `app`.
void addBenchCommand(CLI::App& app, BenchCommandLine& commandLine);

/// Runs the benchmark, prints a table on stdout and writes --json; throws InputError on bad input.
void runBench(const BenchOptions& options);

} // namespace urbis
