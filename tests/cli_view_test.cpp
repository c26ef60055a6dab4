// `urbis view` run as a user runs it: headless, and in a window under Xvfb (the test starts it with
// xvfb-run; it skips, saying so, where there is none). Tolerance: none. The viewer adds sample 0, 1,
// ... of every pixel one frame at a time to the film `urbis render` fills in one call, with the same
// seeds, and writes it through the same code, so its screenshot and the render of its saved scene
// are the same file.
#include "cli_support.h"
#include "png_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <vector>

namespace urbis::test {
namespace {

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }
const char* const kXvfb = "xvfb-run -a -s '-screen 0 1280x1024x24'";

void writeText(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(ViewCli, HeadlessFramesAreTheSamplesRenderTakesAndTheSavedSceneReloads) {
    const auto dir = scratchDir("view_headless");
    const std::string size = "--width 96 --height 54 --buildings 40 --spp 3";
    CommandResult view = runUrbis("view --headless " + size + " --screenshot view.png --save-scene view.json --stats s.json", dir);
    ASSERT_EQ(view.exitCode, 0) << view.err;
    EXPECT_NE(view.out.find("urbis: viewed 3 frames of 96x54 on cpu"), std::string::npos) << view.out;
    EXPECT_NE(readFile(dir / "s.json").find("\"fps\""), std::string::npos);
    CommandResult render = runUrbis("render --scene view.json --out render.png", dir);
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_EQ(readFile(dir / "view.png"), readFile(dir / "render.png"));
    CommandResult again = runUrbis("view --headless --scene view.json --screenshot again.png", dir);
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(readFile(dir / "view.png"), readFile(dir / "again.png"));
    // Denoised while young, the pictures leave the film's sums as they were: with the denoiser turned
    // off before the end, the image is the plain render's still.
    writeText(dir / "undenoise.json", R"({"steps": [{"frame": 3, "set": {"film": {"denoise": false}}}]})");
    CommandResult young = runUrbis("view --headless --scene view.json --denoise --frames 4 --script undenoise.json "
                                   "--screenshot young.png", dir);
    ASSERT_EQ(young.exitCode, 0) << young.err;
    EXPECT_EQ(readFile(dir / "view.png"), readFile(dir / "young.png"));
}

TEST(ViewCli, AScriptRunsInAWindowAndItsScreenshotMatchesRenderOfTheSavedScene) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb): no display to open the viewer on";
    const auto dir = scratchDir("view_window");
    writeText(dir / "fly.json", R"({"steps": [
        {"frame": 0, "mode": "fly"},
        {"frame": 1, "input": {"keys": "WE", "mouse": [60, 20], "seconds": 0.5}},
        {"frame": 2, "set": {"film": {"exposure": 0.5}, "integrator": {"max_depth": 4}}},
        {"frame": 2, "save_scene": "flown.json"},
        {"frame": 6, "quit": true}]})");
    CommandResult view = runUrbis("view --width 640 --height 360 --buildings 40 --spp 4 --script fly.json "
                                  "--screenshot shot.png --window-shot window.png", dir, kXvfb);
    ASSERT_EQ(view.exitCode, 0) << view.err;
    CommandResult render = runUrbis("render --scene flown.json --out render.png", dir);
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_EQ(readFile(dir / "shot.png"), readFile(dir / "render.png"));

    // The window shows the picture: beyond the panel (left) and the overlay (top right), its pixels
    // are the screenshot's (the texture is drawn one texel a pixel).
    const Rgb window = readRgbPng(dir / "window.png"), shot = readRgbPng(dir / "shot.png");
    ASSERT_EQ(window.width, 640u);
    ASSERT_EQ(window.height, 360u);
    ASSERT_EQ(shot.width, 640u);
    size_t differing = 0, compared = 0;
    for (uint32_t y = 200; y < 360; ++y)
        for (uint32_t x = 420; x < 640; ++x, ++compared)
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * 640 + x) * 3 + c;
                differing += std::abs(int(window.pixels[i]) - int(shot.pixels[i])) > 1;
            }
    EXPECT_EQ(differing, 0u) << "of " << compared << " pixels";
}

TEST(ViewCli, AMalformedScriptOrSceneStopsItBeforeAnythingOpens) {
    const auto dir = scratchDir("view_malformed");
    writeText(dir / "bad.json", R"({"steps": [{"frame": 1, "set": {"film": {"exposure": 99}}}]})");
    CommandResult bad = runUrbis("view --headless --width 32 --height 18 --buildings 4 --script bad.json", dir);
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_EQ(bad.err, "urbis: bad.json: the step of frame 1: set: film.exposure: 99 is out of range -20..20\n");
    writeText(dir / "typo.json", R"({"steps": [{"frame": 1, "screenshot": "a.png", "spp": "many"}]})");
    CommandResult typo = runUrbis("view --headless --script typo.json", dir);
    EXPECT_EQ(typo.exitCode, 1);
    EXPECT_EQ(typo.err, "urbis: typo.json: steps[0].spp: expected an integer\n");
    writeText(dir / "scene.json", R"({"film": {"width": 64,}})");
    CommandResult scene = runUrbis("view --headless --scene scene.json", dir);
    EXPECT_EQ(scene.exitCode, 1);
    EXPECT_NE(scene.err.find("urbis: scene.json: malformed JSON at line 1"), std::string::npos) << scene.err;
}

TEST(ViewCli, AProblemOnTheWayIsSaidAndTheViewerGoesOn) {
    const auto dir = scratchDir("view_problem");
    writeText(dir / "broken.json", R"({"film": {"exposure": "bright"}})");
    writeText(dir / "load.json", R"({"steps": [{"frame": 0, "load": "broken.json"}, {"frame": 1, "screenshot": "after.png"}]})");
    const std::string args = "--width 48 --height 27 --buildings 4 --spp 2 --script load.json --frames 3";
    CommandResult headless = runUrbis("view --headless " + args, dir);
    EXPECT_NE(headless.err.find("urbis: broken.json: film.exposure: expected a number\n"), std::string::npos) << headless.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "after.png"));   // it went on
    EXPECT_EQ(headless.exitCode, 1);   // a batch run still fails, at its end
    EXPECT_NE(headless.err.find("1 problem(s) on the way"), std::string::npos);
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb): the windowed half is not run";
    std::filesystem::remove(dir / "after.png");
    CommandResult window = runUrbis("view " + args, dir, kXvfb);
    EXPECT_EQ(window.exitCode, 0) << window.err;
    EXPECT_NE(window.err.find("urbis: broken.json: film.exposure: expected a number\n"), std::string::npos) << window.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "after.png"));
}

TEST(ViewCli, GotoLooksDownOnANamedFeatureOfTheOsmFile) {
    const std::string village = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";
    if (!std::filesystem::exists(village)) GTEST_SKIP() << village << " is absent (Debian: python-osmnx-doc)";
    const auto dir = scratchDir("view_goto");
    const std::string args = "view --headless --width 32 --height 18 --spp 1 --frames 1 --osm '" + village + "' ";
    CommandResult go = runUrbis(args + "--goto goethe --save-scene goethe.json", dir);
    ASSERT_EQ(go.exitCode, 0) << go.err;
    EXPECT_NE(go.err.find("urbis: went to Goethestraße"), std::string::npos) << go.err;
    // 250 m from the street, 30 degrees down: 125 m above the point looked at.
    const nlohmann::json camera = nlohmann::json::parse(readFile(dir / "goethe.json"))["camera"];
    EXPECT_NEAR(camera["position"][1].get<double>() - camera["target"][1].get<double>(), 125.0, 0.5) << camera;
    CommandResult none = runUrbis(args + "--goto 'Coit Tower'", dir);
    EXPECT_EQ(none.exitCode, 1);
    EXPECT_NE(none.err.find("is named like 'Coit Tower'"), std::string::npos) << none.err;
    CommandResult generated = runUrbis("view --headless --width 32 --height 18 --buildings 4 --frames 1 --goto x", dir);
    EXPECT_EQ(generated.exitCode, 1);
    EXPECT_NE(generated.err.find("the generated city has no named features"), std::string::npos) << generated.err;
}

TEST(ViewCli, WithoutADisplayItSaysSoAndHeadlessNeedsNone) {
    const auto dir = scratchDir("view_nodisplay");
    CommandResult view = runUrbis("view --width 32 --height 18 --buildings 4 --frames 1", dir, "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(view.exitCode, 4) << view.err;
    EXPECT_NE(view.err.find("--headless runs without one"), std::string::npos) << view.err;
    CommandResult headless = runUrbis("view --headless --width 32 --height 18 --buildings 4 --frames 1", dir,
                                      "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(headless.exitCode, 0) << headless.err;
}

} // namespace
} // namespace urbis::test
