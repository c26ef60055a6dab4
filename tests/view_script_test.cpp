// Viewer scripts read and refused (each problem named by file and key), scene edits laid over a
// description, and how far a change reaches.
#include "base/input_error.h"
#include "viewer/scene_edit.h"
#include "viewer/view_script.h"

#include <gtest/gtest.h>

#include <string>

namespace urbis {
namespace {

using json = nlohmann::ordered_json;

std::string scriptProblem(const std::string& text) {
    try {
        scriptFromJson(json::parse(text), "s.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ViewScript, ReadsEveryPartOfAStepSortedByFrame) {
    const auto steps = scriptFromJson(json::parse(R"({"steps": [
        {"frame": 9, "screenshot": "a.png", "width": 64, "height": 32, "spp": 4, "quit": true},
        {"frame": 2, "set": {"film": {"exposure": 1}}, "mode": "fly",
         "input": {"keys": "WQ", "mouse": [10, -5], "scroll": 1, "seconds": 0.25}, "undo": true},
        {"frame": 2, "jump": [-122.4, 37.79, 300], "goto": "Ferry Building", "save_scene": "s2.json", "load": "x.json"}]})"), "s.json");
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_EQ(steps[0].frame, 2u);
    EXPECT_EQ(steps[0].set["film"]["exposure"], 1);
    ASSERT_TRUE(steps[0].mode && steps[0].input);
    EXPECT_EQ(*steps[0].mode, CameraMode::Fly);
    EXPECT_TRUE(steps[0].input->forward && steps[0].input->down && !steps[0].input->back);
    EXPECT_TRUE(steps[0].input->dragging);
    EXPECT_FLOAT_EQ(steps[0].input->mouseDy, -5.0f);
    EXPECT_FLOAT_EQ(steps[0].input->seconds, 0.25f);
    EXPECT_TRUE(steps[0].undo);
    EXPECT_EQ(steps[1].saveScene, "s2.json");   // same frame: file order kept
    EXPECT_EQ(steps[1].load, "x.json");
    ASSERT_TRUE(steps[1].jump);
    EXPECT_DOUBLE_EQ((*steps[1].jump)[1], 37.79);
    EXPECT_EQ(steps[1].goTo, "Ferry Building");
    EXPECT_EQ(steps[2].screenshot, "a.png");
    EXPECT_EQ(steps[2].width, 64u);
    EXPECT_TRUE(steps[2].quit);
}

TEST(ViewScript, NamesTheFileTheStepAndTheKeyOfEachProblem) {
    EXPECT_EQ(scriptProblem(R"([1, 2])"), "s.json: expected an object {\"steps\": [...]} (docs/viewer.md)");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"frame": -1}]})"), "s.json: steps[0].frame: -1 is out of range 0..1000000000");
    EXPECT_EQ(scriptProblem(R"({"steps": [{}, {"frmae": 1}]})").substr(0, 35), "s.json: steps[1].frmae: unknown key");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"input": {"keys": "WX"}}]})"),
              "s.json: steps[0].input.keys: 'X' is none of the keys W, A, S, D, Q, E");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"mode": "walk"}]})"), "s.json: steps[0].mode: expected \"orbit\" or \"fly\"");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"width": 10}]})"), "s.json: steps[0].width: width, height and spp belong to a screenshot");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"jump": [200, 0, 10]}]})"),
              "s.json: steps[0].jump: need |LON| <= 180, |LAT| <= 90 degrees and 0 <= ALTITUDE <= 1e6 metres");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"goto": 3}]})"), "s.json: steps[0].goto: expected the name of an OSM feature");
    EXPECT_EQ(scriptProblem(R"({"steps": [{"set": 3}]})"), "s.json: steps[0].set: expected an object shaped like a scene file");
}

TEST(SceneEdit, PatchesAreReadAsSceneFilesAre) {
    const SceneDescription d;
    const SceneDescription e = patchedScene(d, json::parse(R"({"film": {"exposure": 2.5}, "camera": {"position": [1, 2, 3], "target": [4, 5, 6]}})"), "edit");
    EXPECT_FLOAT_EQ(e.film.exposure, 2.5f);
    ASSERT_TRUE(e.camera.position);
    EXPECT_FLOAT_EQ(e.camera.position->y, 2.0f);
    EXPECT_EQ(e.film.width, d.film.width);   // the keys left out keep their values
    // null unsets an optional key.
    EXPECT_FALSE(patchedScene(e, json::parse(R"({"camera": {"position": null, "target": null}})"), "edit").camera.position);
    try {
        patchedScene(d, json::parse(R"({"film": {"exposure": 99}})"), "edit");
        FAIL() << "an exposure out of range was taken";
    } catch (const InputError& err) {
        EXPECT_EQ(std::string(err.what()), "edit: film.exposure: 99 is out of range -20..20");
    }
}

TEST(SceneEdit, ChangesReachAsFarAsTheyMust) {
    const SceneDescription d;
    SceneDescription e = d;
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::None);
    e.film.output = "other.png";
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::None);
    e.film.exposure += 1;
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::Display);
    e.integrator.maxDepth = 3;
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::Restart);
    e.camera.fov = 30;
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::Restart);
    e.film.width = 100;
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::Resize);
    e.astronomy.time = "2024-06-21T21:30+02:00";
    EXPECT_EQ(sceneChangeOf(d, e), SceneChange::Rebuild);
    SceneDescription g = d;
    g.geometry.streets = false;
    EXPECT_EQ(sceneChangeOf(d, g), SceneChange::Rebuild);
}

} // namespace
} // namespace urbis
