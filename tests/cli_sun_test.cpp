// `urbis sun`, and --time / --location on render: the JSON a user or a test can check, the errors
// (one line, the exit codes of docs/cli.md), and the scene keys they set.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    return scratchDir(std::string("sun_") + testing::UnitTest::GetInstance()->current_test_info()->name());
}

TEST(CliSun, PrintsTheSunAndTheMoonAsJson) {
    const fs::path dir = testDir();
    // NREL SPA's published example (NREL/TP-560-34302, table A5.1): zenith 50.11162, azimuth 194.34024.
    const CommandResult r = runUrbis("sun --location -105.1786,39.742476 --time 2003-10-17T12:30:30-07:00 --json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json out = nlohmann::json::parse(r.out);
    EXPECT_NEAR(out["elevation"].get<double>(), 90.0 - 50.11162, 0.1);
    EXPECT_NEAR(out["azimuth"].get<double>(), 194.34024, 0.1);
    for (const char* key : {"elevation", "azimuth", "illuminated_fraction", "phase_angle", "angular_radius"})
        EXPECT_TRUE(out["moon"].contains(key)) << key;
    EXPECT_NEAR(out["moon"]["angular_radius"].get<double>(), 0.26, 0.02);
    EXPECT_NEAR(out["local_hour"].get<double>(), 12.5083333, 1e-6);
    EXPECT_EQ(out["time"], "2003-10-17T12:30:30-07:00");
    EXPECT_EQ(out["location"][1], 39.742476);
}

TEST(CliSun, PrintsALineWithoutJson) {
    const fs::path dir = testDir();
    const CommandResult r = runUrbis("sun --time 2024-06-21T12:00+02:00", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_NE(r.out.find("sun: elevation 6"), std::string::npos) << r.out;  // Prague at midsummer noon: about 63 degrees
    EXPECT_NE(r.out.find("14.4213,50.0875"), std::string::npos) << "the default place: " << r.out;
}

TEST(CliSun, BadInputIsOneLineAndExitTwo) {
    const fs::path dir = testDir();
    const std::pair<const char*, const char*> cases[] = {
        {"sun --time 2024-06-21T20:30", "--time: '2024-06-21T20:30': no UTC offset"},
        {"sun --time 2024-02-30T20:30Z", "day 30 is not in 2024-02"},
        {"sun --time 2024-06-21T20:30Z --location 200,10", "--location: need LON in [-180, 180]"},
        {"sun --time 2024-06-21T20:30Z --location 10", "--location"},
        {"sun --json", "--time is required"},
        {"render --time tomorrow --out x.png", "--time: 'tomorrow': expected YYYY-MM-DDTHH:MM"},
        {"render --location 0,95 --out x.png", "--location: need LON in [-180, 180] and LAT in [-90, 90]"},
    };
    for (const auto& [args, message] : cases) {
        const CommandResult r = runUrbis(args, dir);
        EXPECT_EQ(r.exitCode, 2) << args << " -> " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": not one line: " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << " -> " << r.err;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << args;
    }
}

TEST(CliSun, TimeAndLocationAreSceneKeys) {
    const fs::path dir = testDir();
    ASSERT_EQ(runUrbis("render --width 16 --height 16 --spp 1 --buildings 5 --time 2024-06-21T22:30+02:00 "
                       "--location 2.35,48.85 --sun 20,100 --save-scene s.json",
                       dir).exitCode, 0);
    const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "s.json"));
    EXPECT_EQ(scene["astronomy"]["time"], "2024-06-21T22:30+02:00");
    EXPECT_EQ(scene["astronomy"]["location"], nlohmann::json::array({2.35, 48.85}));
    EXPECT_EQ(scene["astronomy"]["sun_from_time"], false) << "--sun overrides the time's sun";
    // A bad time in a file is the file's error: exit 1, naming the key.
    std::ofstream(dir / "bad.json") << R"({"astronomy": {"time": "2024-06-21T25:00Z"}})";
    const CommandResult r = runUrbis("render --scene bad.json --out x.png", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("bad.json: astronomy.time: '2024-06-21T25:00Z': hour 25 is not 0..23"), std::string::npos) << r.err;
}

} // namespace
