// Scene files: a SceneDescription as JSON (docs/scene_files.md), read with every problem named by
// its key path, and written complete (every key with its value).
#pragma once

#include "description/scene_description.h"

#include <nlohmann/json.hpp>

#include <string>

namespace urbis {

/// The description `json` holds, over `defaults` for the keys it leaves out (a command's own:
/// bench's differ from render's). `file` names the source in messages. Throws a bad-input InputError of one line, "FILE: KEY.PATH: problem", on an
/// unknown key, a wrong type, a value out of range or fields that contradict each other (see
/// checkSceneDescription). Relative paths are kept as written.
SceneDescription sceneFromJson(const nlohmann::ordered_json& json, const std::string& file,
                               const SceneDescription& defaults = {});

/// Every key of `description` with its value, in the order of docs/scene_files.md; null for the
/// optional fields it leaves unset.
nlohmann::ordered_json sceneToJson(const SceneDescription& description);

/// A float as the double of its shortest decimal text, so that a file says 0.27 and not
/// 0.27000001072883606, and reads back as the same float.
nlohmann::ordered_json floatJson(float value);

/// sceneToJson as the text of a scene file: indented, each array of numbers on one line.
std::string sceneFileText(const SceneDescription& description);

/// Reads the scene file at `path` (sceneFromJson), naming the file on a missing or unreadable file
/// and the line and column of malformed JSON. A relative source.osm is taken relative to the
/// file's folder. The keys the file leaves out keep `defaults`.
SceneDescription readSceneFile(const std::string& path, const SceneDescription& defaults = {});

/// The JSON of the file at `path`; an InputError names the file (and `what` it should be: "scene
/// file") when it is missing or unreadable, and the line and column of malformed JSON.
nlohmann::ordered_json readJsonFile(const std::string& path, const std::string& what);

/// Writes `description` to `path` through a temporary, with a relative source.osm rewritten
/// relative to the folder of `path` (so that readSceneFile finds the same file).
void writeSceneFile(const SceneDescription& description, const std::string& path);

} // namespace urbis
