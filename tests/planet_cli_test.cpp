// `urbis render --planet` and `--camera-orbit` from the command line and scene files (docs/planets.md).
#include "cli_support.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kSmall = "render --width 48 --height 32 --spp 1 ";

} // namespace

// Deterministic whatever the thread count, and a scene file saved from it renders the same image.
TEST(PlanetCli, RendersTheSameImageOnAnyThreadCountAndFromItsSavedScene) {
    const fs::path dir = scratchDir("planet_cli_render");
    const std::string planet = kSmall + "--planet 3000 --camera-orbit 5,30,0,90,-20 ";
    ASSERT_EQ(runUrbis(planet + "--threads 1 --out one.png --save-scene planet.json", dir).exitCode, 0);
    ASSERT_EQ(runUrbis(planet + "--threads 2 --out two.png", dir).exitCode, 0);
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png"));
    const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "planet.json"));
    EXPECT_EQ(scene["planet"]["radius_km"], 3000.0);
    EXPECT_EQ(scene["planet"]["camera"]["altitude_km"], 5.0);
    EXPECT_EQ(scene["planet"]["camera"]["heading"], 90.0);
    ASSERT_EQ(runUrbis("render --scene planet.json --threads 1 --out file.png", dir).exitCode, 0);
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "file.png"));
}

// Wrong input: one line naming the problem, exit 2, no image.
TEST(PlanetCli, BadPlanetOptionsGiveOneLineAndExitTwo) {
    const fs::path dir = scratchDir("planet_cli_bad");
    for (const std::string args : {"--camera-orbit 10,0,0", "--planet 5", "--planet abc", "--planet --camera-orbit 10,95,0",
                                   "--planet --camera-orbit 10,0", "--planet --camera-orbit 10,0,0,0,-100",
                                   "--planet --camera-orbit -1,0,0"}) {
        const CommandResult r = runUrbis(kSmall + args + " --out out.png", dir);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out.png")) << args;
    }
}

// A scene file's planet is checked like every other key: the amplitude against the radius.
TEST(PlanetCli, SceneFileOfATooRoughPlanetIsRefused) {
    const fs::path dir = scratchDir("planet_cli_rough");
    std::ofstream(dir / "rough.json") << R"({"planet": {"radius_km": 100, "amplitude": 30000}})";
    const CommandResult r = runUrbis(kSmall + "--scene rough.json --out out.png", dir);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("planet.amplitude"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}
