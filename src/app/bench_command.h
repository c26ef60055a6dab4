// `urbis bench`: rays per second of primary, diffuse and shadow rays, and the time of a path-traced frame.
#pragma once

#include "app/render_command.h"

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct BenchOptions {
    RenderOptions scene;        ///< city, size, camera, sun; settings.width/height are the frame's
    std::string jsonFile;
    int repeats = 0;            ///< timed runs per measurement; 0: 20 on the GPU, 3 on the CPU
    int warmup = 3;             ///< untimed runs before them (GPU)
};

/// Registers the subcommand's options on `app`.
void addBenchCommand(CLI::App& app, BenchOptions& options);

/// Runs the benchmark, prints a table on stdout and writes --json; throws InputError on bad input.
void runBench(const BenchOptions& options);

} // namespace urbis
