// `urbis render`: load or generate a city, mesh it, build the BVH, path trace, write PNG and stats.
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
    float metresPerLevel = 3.0f;
    std::string device = "auto";      ///< "auto", "cpu" or "cuda"
    std::string geometry = "procedural";  ///< --geometry: representation per kind (see parseGeometryModes)
    float heightScale = 1.0f;             ///< multiplies every building's height (benchmarks of tall cities)
    std::string wallTiles = "whole";      ///< --wall-tiles: "whole" or "SLOTSxFLOORS" (splitWallsIntoTiles)
};

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

/// Everything before the render itself, shared by `urbis render` and `urbis bench`; throws InputError on bad input.
PreparedScene prepareScene(const RenderOptions& options);

/// Registers the subcommand's options on `app`.
void addRenderCommand(CLI::App& app, RenderOptions& options);

/// Runs the render; throws InputError on bad input.
void runRender(const RenderOptions& options);

} // namespace urbis
