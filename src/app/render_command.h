// `urbis render`: load or generate a city, mesh it, build the BVH, path trace, write PNG or EXR and stats.
#pragma once

#include "citygen/city_mesher.h"
#include "model/city_model.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct RenderOptions {
    std::string osmFile;              ///< empty: the generated city
    std::string outFile = "urbis.png";
    std::string statsFile;
    RenderSettings settings;
    unsigned threads = 0;             ///< 0: all cores
    uint64_t buildings = 400;         ///< size of the generated city
    std::string heightRange;          ///< "min:max" metres for untagged buildings; empty: estimated (OSM) or the layout default
    std::string bbox;                 ///< "minLon,minLat,maxLon,maxLat"
    std::string camera;               ///< "x,y,z,tx,ty,tz" world metres
    std::string cameraGeo;            ///< "lon,lat,altitude,heading,pitch"
    float fovDeg = 50.0f;
    std::string sun = "40,150";       ///< "elevation,azimuth" degrees
    float sunRadiusDeg = 0.27f;
    float exposureEv = -0.6f;
    bool exrFloat = false;            ///< --exr-float: EXR colour, albedo and normal as float, not half
    float metresPerLevel = 3.0f;
    std::string device = "auto";      ///< "auto", "cpu" or "cuda"
    std::string geometry = "procedural";  ///< --geometry: representation per kind (see parseGeometryModes)
    float heightScale = 1.0f;             ///< multiplies every building's height (benchmarks of tall cities)
    std::string wallTiles = "whole";      ///< --wall-tiles: "whole" or "SLOTSxFLOORS" (splitWallsIntoTiles)
    std::string maxMemory;                ///< --max-memory: empty for the default (see memoryLimit)
    bool strict = false;                  ///< warnings (the camera checks) are errors
    bool verbose = false;                 ///< say which device renders and why
};

/// The largest --width and --height; the memory check (--max-memory) bounds their product.
inline constexpr uint32_t kMaxImageSide = 65536;

/// A city loaded (or generated), meshed and turned into a scene with its BVH, ground and sun,
/// and the camera the options ask for; with the time of each step in seconds.
struct PreparedScene {
    CityModel city;
    CityMesh mesh;
    Scene scene;
    Camera camera;
    GeometryModes geometry;   ///< --geometry as parsed
    double secondsImport = 0, secondsCitygen = 0, secondsBvh = 0;
};

/// Everything before the render itself, shared by `urbis render` and `urbis bench`: the city
/// loaded and meshed (a triangle twin within `memoryLimit` bytes, 0: no limit) and the camera,
/// checked (cameraProblems: warnings on stderr, errors with --strict). Throws InputError.
PreparedScene prepareScene(const RenderOptions& options, size_t memoryLimit);

/// Registers the subcommand's options on `app`.
void addRenderCommand(CLI::App& app, RenderOptions& options);

/// Registers --max-memory, --strict and --verbose, which render and bench share, on `cmd`.
void addRunOptions(CLI::App& cmd, RenderOptions& options);

/// Checks the outputs and the image's memory, then renders and writes --out and --stats, and
/// ends with one line on stdout saying what it wrote and how long it took. Throws InputError.
void runRender(const RenderOptions& options);

} // namespace urbis
