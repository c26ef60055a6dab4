// The one list of the scene's keys (description/scene_fields.h): every key carries what the command
// line and the panel need, and the list and the scene file agree, key for key.
#include "description/scene_field_list.h"
#include "description/scene_json.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

using namespace urbis;
using json = nlohmann::ordered_json;

namespace {

/// The value at `path` ("integrator.max_depth") of `root`, or null.
json valueAt(const json& root, const std::string& path) {
    const json* node = &root;
    size_t start = 0;
    while (start <= path.size()) {
        const size_t dot = std::min(path.find('.', start), path.size());
        const std::string key = path.substr(start, dot - start);
        if (!node->is_object() || !node->contains(key)) return json();
        node = &(*node)[key];
        start = dot + 1;
    }
    return *node;
}

/// Every key path of a scene file's leaves (the values that are no objects), objects with a Field
/// of their own (a colour map, an optional object) as leaves too.
void leavesOf(const json& node, const std::string& path, const std::set<std::string>& fieldPaths, std::set<std::string>& out) {
    if (!node.is_object() || fieldPaths.count(path)) {
        out.insert(path);
        if (!node.is_object() || !fieldPaths.count(path)) return;
        if (path == "materials.wall_colour_by_type" || path == "materials.roof_colour_by_type") return;
    }
    for (const auto& [key, value] : node.items()) leavesOf(value, path.empty() ? key : path + "." + key, fieldPaths, out);
}

SceneDescription withEveryOptionalObject() {
    SceneDescription d;
    d.camera.geo = GeoCameraDescription{};
    d.planet = PlanetDescription{};
    return d;
}

} // namespace

TEST(DescriptionFields, EveryKeyHasItsOptionAndHelp) {
    const json file = sceneToJson(withEveryOptionalObject());
    ASSERT_FALSE(sceneFieldList().empty());
    for (const FieldAtPath& f : sceneFieldList()) {
        EXPECT_FALSE(std::string(f.field.help).empty()) << f.path << ": the panel's tooltip and the option's help";
        if (!f.field.flag) {
            EXPECT_TRUE(valueAt(file, f.path).is_array()) << f.path << ": only keyframe arrays have no option";
            continue;
        }
        const std::string flag = f.field.flag;
        EXPECT_TRUE(flag.size() > 2 && flag.rfind("--", 0) == 0) << f.path << ": " << flag;
        for (char c : flag.substr(2)) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(c) || c == '-') << flag;
    }
}

TEST(DescriptionFields, TheListIsTheSceneFilesKeys) {
    std::set<std::string> listed;
    for (const FieldAtPath& f : sceneFieldList()) EXPECT_TRUE(listed.insert(f.path).second) << f.path << " listed twice";
    std::set<std::string> inFile;
    leavesOf(sceneToJson(withEveryOptionalObject()), "", listed, inFile);
    EXPECT_EQ(inFile, listed);
}

TEST(DescriptionFields, AChangeReachesAsFarAsItsKeySays) {
    for (const FieldAtPath& f : sceneFieldList()) {
        const std::string section = f.path.substr(0, f.path.find('.'));
        if (section == "camera" || section == "integrator") {
            EXPECT_EQ(f.field.change, SceneChange::Restart) << f.path << ": the same scene, the image starts over";
        }
        if (section == "sun" || section == "sky" || section == "astronomy" || section == "lights") {
            EXPECT_EQ(f.field.change, SceneChange::Relight) << f.path;
        }
    }
}

TEST(DescriptionFields, ASceneFileReadsOverTheCommandsDefaults) {
    SceneDescription defaults;
    defaults.film.width = 1920;
    defaults.integrator.spp = 1;
    const SceneDescription d = sceneFromJson(json::parse(R"({"trees": {"enabled": false}})"), "f.json", defaults);
    EXPECT_EQ(d.film.width, 1920u);
    EXPECT_EQ(d.integrator.spp, 1u);
    EXPECT_FALSE(d.trees.enabled);
}
