// `urbis render`: load or generate a city, mesh it, build the BVH, path trace, write PNG and stats.
#pragma once

#include "app/scene_options.h"
#include "citygen/window_schedule.h"
#include "cluster/mpi_world.h"
#include "scene/geometry_modes.h"
#include "description/scene_description.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <map>
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

/// What the stats say about the import and the meshing, kept once the city and its mesh are
/// released (they are build-time data: the scene holds its own copy of every triangle).
struct BuildSummary {
    std::string source;                         ///< CityModel::source
    size_t buildings = 0;
    nlohmann::json counts, dropped, repaired;   ///< the stats' objects of the same names
    std::map<std::string, size_t> trianglesByKind;
    size_t facadeWalls = 0, facadeCells = 0;
};

/// A city loaded (or generated), meshed and turned into a scene with its BVH, ground and lights,
/// and the camera the description asks for; with the time of each step in seconds.
struct PreparedScene {
    BuildSummary summary;
    Scene scene;
    Camera camera;
    GeometryModes geometry;
    double secondsImport = 0, secondsCitygen = 0, secondsBvh = 0;
    GeoOrigin origin;                     ///< the city's (valid for OSM): where cameraOf places geographic cameras
    std::vector<WindowUse> windowUses;    ///< each building's, by index: relightWindows for another hour
    std::vector<Bounds3f> framingPieces;  ///< what cameraOf frames when the description names no camera
};

/// Everything before the render itself, shared by `urbis render` and `urbis bench`: the city of
/// `scene.source` loaded and meshed (a triangle twin within `memoryLimit` bytes, 0: no limit), the
/// camera chosen and checked (cameraProblems: warnings on stderr, errors when `strict`), the scene
/// built; the city and its mesh are released before it returns. Throws InputError.
PreparedScene prepareScene(const SceneDescription& scene, bool strict, size_t memoryLimit);

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
