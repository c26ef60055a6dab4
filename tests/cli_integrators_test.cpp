// Every integrator in every front-end, run as a user runs them (CPU): the viewer's headless frames and
// its screenshot, the still of `urbis render`, a `--frames` sequence and `urbis bench`. Tolerance: none.
// The viewer adds sample 0, 1, ... one frame at a time through the same Renderer that `render` drives
// in one call, light pass before camera pass for each sample, so its screenshot and the render of its
// saved scene are the same file.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace urbis::test {
namespace {

const char* const kIntegrators[] = {"path", "photon-map", "photon-buffers"};

TEST(CliIntegrators, TheViewerOfAPhotonIntegratorRunsItsPhotonPass) {
    const auto dir = scratchDir("integrators_view_crash");
    // The photon map's gather once read a grid nobody built here (exit 139).
    const CommandResult r = runUrbis("view --headless --frames 3 --width 64 --height 40 --integrator photon-map", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("urbis: viewed 3 frames of 64x40"), std::string::npos) << r.out;
}

TEST(CliIntegrators, EachIntegratorsViewerScreenshotIsItsRender) {
    const auto dir = scratchDir("integrators_view");
    for (const std::string integrator : kIntegrators) {
        const std::string size = "--width 48 --height 32 --buildings 30 --spp 3 --photons 3000 --integrator " + integrator;
        const CommandResult view =
            runUrbis("view --headless " + size + " --screenshot view.png --save-scene view.json", dir);
        ASSERT_EQ(view.exitCode, 0) << integrator << ": " << view.err;
        const CommandResult render = runUrbis("render --scene view.json --out render.png", dir);
        ASSERT_EQ(render.exitCode, 0) << integrator << ": " << render.err;
        EXPECT_EQ(readFile(dir / "view.png"), readFile(dir / "render.png")) << integrator;
    }
}

TEST(CliIntegrators, EachIntegratorRendersASequenceAndBenches) {
    const auto dir = scratchDir("integrators_frames");
    std::ofstream(dir / "anim.json") << R"({"source": {"buildings": 30, "seed": 3}, "integrator": {"spp": 2},
        "film": {"width": 40, "height": 24}, "photons": {"per_pass": 2000}, "animation": {"fps": 1,
        "camera": [{"time": 0, "position": [200, 100, 60], "target": [0, 10, 0]},
                   {"time": 1, "position": [-150, 80, 120], "target": [0, 10, 0]}]}})";
    for (const std::string integrator : kIntegrators) {
        const CommandResult frames = runUrbis("render --scene anim.json --integrator " + integrator +
                                                  " --frames 0:1 --out " + integrator + "/f%d.png", dir);
        ASSERT_EQ(frames.exitCode, 0) << integrator << ": " << frames.err;
        // Frame 1 alone is frame 1 of the sequence: whichever renderer takes a frame, it starts afresh.
        const CommandResult alone = runUrbis("render --scene anim.json --integrator " + integrator + " --frames 1 --out " +
                                                 integrator + "_alone/f%d.png", dir);
        ASSERT_EQ(alone.exitCode, 0) << integrator << ": " << alone.err;
        EXPECT_EQ(readFile(dir / integrator / "f1.png"), readFile(dir / (integrator + "_alone") / "f1.png")) << integrator;
        const CommandResult bench = runUrbis("bench --device cpu --buildings 30 --width 40 --height 24 --repeats 1 --photons 2000 "
                                             "--integrator " + integrator + " --json b.json", dir);
        ASSERT_EQ(bench.exitCode, 0) << integrator << ": " << bench.err;
        const nlohmann::json json = nlohmann::json::parse(readFile(dir / "b.json"));
        EXPECT_GT(json.at("frame").at("median_ms").get<double>(), 0.0) << integrator;
    }
}

} // namespace
} // namespace urbis::test
