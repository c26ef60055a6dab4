// `urbis render`: load or generate a city, mesh it, build the BVH, path trace, write PNG and stats.
#pragma once

#include "app/scene_options.h"
#include "cluster/mpi_world.h"
#include "description/scene_description.h"
#include "prepare/prepared_scene.h"

#include <CLI/CLI.hpp>
#include <string>

namespace urbis {

/// How a command runs, apart from the scene it renders: threads, device, limits, extra outputs.
struct RunOptions {
    std::string statsFile;
    unsigned threads = 0;             ///< 0: all cores
    std::string device = "auto";      ///< "auto", "cpu" or "cuda"
    std::string devices;              ///< --devices all|0,1,...: the CUDA devices of one process (devicesOf); empty: one
    std::string maxMemory;            ///< --max-memory: empty for the default (see memoryLimit)
    bool strict = false;              ///< warnings (the camera checks) are errors
    bool verbose = false;             ///< say which device renders and why
};

/// Which frames of the scene's animation to render (docs/animation.md); none: the still.
struct FrameOptions {
    std::string frames;               ///< --frames A:B, A or A:; empty: the still
    bool overwrite = false;           ///< render the frames whose files exist too
    std::string video;                ///< --video: a .mp4 or .gif ffmpeg encodes from the frames; empty: none
};

/// A render: the scene description and how to run it.
struct RenderOptions {
    SceneDescription scene;
    RunOptions run;
    std::string saveSceneFile;        ///< --save-scene; empty: none
    FrameOptions frames;
};

/// The command line of `urbis render`, resolved into RenderOptions once parsed.
struct RenderCommandLine {
    SceneCommandLine scene;
    RunOptions run;
    FrameOptions frames;
    RenderOptions resolve() const { return {scene.resolve(), run, scene.saveScenePath(), frames}; }
};

/// Registers the subcommand's options on `app`.
void addRenderCommand(CLI::App& app, RenderCommandLine& commandLine);

/// Registers --max-memory, --strict and --verbose, which render and bench share, on `cmd`.
void addRunOptions(CLI::App& cmd, RunOptions& options);

/// Checks the outputs and the image's memory, then renders and writes the image, --stats and
/// --save-scene, and ends with one line on stdout saying what it wrote and how long it took.
/// Under mpirun (`world` of more than one rank) every rank builds the scene, the ranks share the
/// frame's tiles (renderAcrossRanks) and rank 0 alone writes the files. Throws InputError.
void runRender(const RenderOptions& options, const MpiWorld* world = nullptr);

} // namespace urbis
