// From a scene description to a scene: the city loaded (or generated) and meshed, or the planet built;
// the camera chosen and checked; the BVH, the ground, the clouds and the lights (docs/architecture.md).
#pragma once

#include "citygen/window_schedule.h"
#include "description/scene_description.h"
#include "scene/camera.h"
#include "scene/geometry_modes.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace urbis {

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

} // namespace urbis
