// Viewer scripts (docs/viewer.md): timed camera moves and parameter changes, screenshots and saved
// scene files, for tests, benchmarks and recorded fly-throughs. A script is a JSON object
//   {"steps": [{"frame": 0, "load": "city.json"}, {"frame": 0, "set": {"film": {"exposure": 1}}},
//              {"frame": 4, "input": {"keys": "W", "mouse": [40, 0], "seconds": 0.5, "mode": "fly"}},
//              {"frame": 8, "undo": true}, {"frame": 9, "jump": [-122.397, 37.789, 300]},
//              {"frame": 10, "goto": "Ferry Building"},
//              {"frame": 12, "screenshot": "a.png", "width": 1920, "height": 1080, "spp": 64},
//              {"frame": 16, "save_scene": "a.json"}, {"frame": 20, "quit": true}]}
// whose steps run, in order, before the frame of their number is rendered.
#pragma once

#include "viewer/view_camera.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// One step of a script; each of its parts is optional, and they run in the order listed here.
struct ScriptStep {
    uint32_t frame = 0;                      ///< before this frame (0: the first) is rendered
    std::string load;                        ///< a scene file made the scene; empty: none
    nlohmann::ordered_json set;              ///< part of a scene file laid over the scene (patchedScene); null: none
    std::optional<CameraMode> mode;          ///< "orbit" or "fly"
    std::optional<CameraInput> input;        ///< keys held and mouse moved (dragging) for `seconds`
    bool undo = false;                       ///< the camera's last move undone
    std::optional<std::array<double, 3>> jump;   ///< LON, LAT (degrees), ALTITUDE (metres above the ground)
    std::string goTo;                        ///< "goto": the name of an OSM feature to look down on; empty: none
    std::string screenshot;                  ///< PNG or EXR rendered offline; empty: none
    uint32_t width = 0, height = 0, spp = 0; ///< of the screenshot; 0: the film's size, the frames taken so far
    std::string saveScene;                   ///< the scene file written; empty: none
    bool quit = false;                       ///< the viewer ends after this step
};

/// The steps of the script `json` read from `file`, sorted by frame (steps of one frame in file
/// order). Throws a bad-input InputError "FILE: steps[I].KEY: problem" on anything else.
std::vector<ScriptStep> scriptFromJson(const nlohmann::ordered_json& json, const std::string& file);

/// Reads the script file at `path`: scriptFromJson, with a missing file or malformed JSON named.
std::vector<ScriptStep> readScriptFile(const std::string& path);

} // namespace urbis
