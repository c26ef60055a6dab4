// The `animation` section of a scene file (docs/animation.md): read with every problem as one line
// naming the file and the key path, and written back with the keys each keyframe gives.
#pragma once

#include "description/animation_description.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace urbis {

/// Reads `node` (the value of `path`, "animation", in `file`), walking visitAnimationFields. Throws InputError "FILE: PATH.KEY:
/// problem" on an unknown key, a value of the wrong type or out of range, a keyframe without a time
/// or without a position, times that do not increase, a position given both ways, a look given both
/// ways or a heading without a pitch, a date that is no ISO 8601 time with an offset.
AnimationDescription animationFromJson(const nlohmann::ordered_json& node, const std::string& file, const std::string& path);

/// The section as a scene file holds it: fps, duration, and the keyframes with the keys they give.
nlohmann::ordered_json animationToJson(const AnimationDescription& animation);

/// The camera keyframes of the array `node` (the value of `path`, "animation.camera", in `file`),
/// checked as animationFromJson says.
std::vector<CameraKeyframe> cameraKeyframesFromJson(const nlohmann::ordered_json& node, const std::string& file,
                                                    const std::string& path);

/// The time keyframes of the array `node` (the value of `path`, "animation.time", in `file`), checked
/// as animationFromJson says.
std::vector<TimeKeyframe> timeKeyframesFromJson(const nlohmann::ordered_json& node, const std::string& file,
                                                const std::string& path);

/// The keyframes as a scene file holds them, each with the keys it gives.
nlohmann::ordered_json keyframesToJson(const std::vector<CameraKeyframe>& keyframes);
nlohmann::ordered_json keyframesToJson(const std::vector<TimeKeyframe>& keyframes);

} // namespace urbis
