#include "viewer/scene_edit.h"

#include "description/scene_field_list.h"
#include "description/scene_json.h"

#include <algorithm>
#include <map>

namespace urbis {

namespace {

using json = nlohmann::ordered_json;

/// How far a change at key path `path` reaches: its field's change, or that of the nearest field
/// around it (a colour map's entry, a keyframe's key). A path that no field names rebuilds.
SceneChange reachOf(std::string path) {
    static const std::map<std::string, SceneChange> reach = [] {
        std::map<std::string, SceneChange> m;
        for (const FieldAtPath& f : sceneFieldList()) m[f.path] = f.field.change;
        return m;
    }();
    for (;;) {
        if (const auto it = reach.find(path); it != reach.end()) return it->second;
        const size_t dot = path.rfind('.');
        if (dot == std::string::npos) return SceneChange::Rebuild;
        path.resize(dot);
    }
}

/// Raises `change` to the reach of every value that differs between `a` and `b` (at `path`).
void compare(const json& a, const json& b, const std::string& path, SceneChange& change) {
    if (a.is_object() && b.is_object()) {
        const auto at = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
        for (const auto& [key, x] : a.items()) compare(x, b.contains(key) ? b[key] : json(), at(key), change);
        for (const auto& [key, y] : b.items())
            if (!a.contains(key)) compare(json(), y, at(key), change);
        return;
    }
    if (a != b) change = std::max(change, reachOf(path));
}

} // namespace

SceneDescription patchedScene(const SceneDescription& d, const nlohmann::ordered_json& patch, const std::string& where) {
    nlohmann::ordered_json json = sceneToJson(d);
    json.merge_patch(patch);
    return sceneFromJson(json, where);
}

SceneChange sceneChangeOf(const SceneDescription& before, const SceneDescription& after) {
    SceneChange change = SceneChange::None;
    compare(sceneToJson(before), sceneToJson(after), "", change);
    // The viewer relights by building the scene again (view_session.cpp has no step of its own for it).
    return change == SceneChange::Relight ? SceneChange::Rebuild : change;
}

} // namespace urbis
