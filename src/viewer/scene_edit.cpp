#include "viewer/scene_edit.h"

#include "description/scene_json.h"

#include <algorithm>
#include <string_view>

namespace urbis {

SceneDescription patchedScene(const SceneDescription& d, const nlohmann::ordered_json& patch, const std::string& where) {
    nlohmann::ordered_json json = sceneToJson(d);
    json.merge_patch(patch);
    return sceneFromJson(json, where);
}

SceneChange sceneChangeOf(const SceneDescription& before, const SceneDescription& after) {
    const nlohmann::ordered_json a = sceneToJson(before), b = sceneToJson(after);
    // Film keys that only the written files read: the viewer's image does not change with them.
    constexpr std::string_view kFileKeys[] = {"output", "layers", "exr_float"};
    SceneChange change = SceneChange::None;
    const auto raise = [&](SceneChange c) { change = std::max(change, c); };
    for (const auto& [section, value] : a.items()) {
        if (b.contains(section) && b[section] == value) continue;
        if (section == "camera" || section == "integrator") {
            raise(SceneChange::Restart);
        } else if (section == "film") {
            for (const auto& [key, x] : value.items()) {
                if (b[section].value(key, nlohmann::ordered_json()) == x) continue;
                if (key == "width" || key == "height") raise(SceneChange::Resize);
                else if (key == "exposure" || key == "denoise") raise(SceneChange::Display);
                else if (std::find(std::begin(kFileKeys), std::end(kFileKeys), key) == std::end(kFileKeys)) raise(SceneChange::Restart);
            }
        } else {
            raise(SceneChange::Rebuild);
        }
    }
    return change;
}

} // namespace urbis
