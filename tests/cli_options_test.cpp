// The scene's command-line options, made from its fields (description/scene_fields.h): every key has
// its option on `render` and `view`, the options of keys that had none set them, and bench keeps its
// own defaults under a scene file that leaves them out.
#include "cli_support.h"
#include "description/scene_field_list.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>

using namespace urbis;
using namespace urbis::test;

namespace {

const std::string kTiny = "render --width 8 --height 8 --spp 1 --buildings 4 ";

std::filesystem::path testDir() {
    return scratchDir(std::string("options_") + testing::UnitTest::GetInstance()->current_test_info()->name());
}

} // namespace

TEST(CliOptions, EveryKeyHasItsOptionOnRenderAndView) {
    const std::filesystem::path dir = testDir();
    for (const char* command : {"render", "view"}) {
        const CommandResult help = runUrbis(std::string(command) + " --help", dir);
        ASSERT_EQ(help.exitCode, 0) << help.err;
        for (const FieldAtPath& f : sceneFieldList()) {
            if (!f.field.flag) continue;   // keyframe arrays: the scene file's alone
            const std::string flag = f.field.flag;
            const bool listed = help.out.find("  " + flag + " ") != std::string::npos ||
                                help.out.find("  " + flag + "\n") != std::string::npos ||
                                help.out.find(flag + " ") != std::string::npos;
            EXPECT_TRUE(listed) << command << " --help lacks " << flag << " (" << f.path << ")";
        }
    }
}

TEST(CliOptions, OptionsOfEveryKindSetTheirKeys) {
    const std::filesystem::path dir = testDir();
    const CommandResult r = runUrbis(kTiny + "--no-water --trees-seed 5 --sky-zenith 0.5,0.25,1 --exr-layers albedo,depth "
                                             "--wall-colour house=0.5,0.1,0.1 --wall-colour shed=0.2,0.2,0.2 --lights-hour 21 "
                                             "--fbm-octaves 4 --duration 2 --clouds-type stratus --dual-heightmap "
                                             "--sun-from-time=false --out o.png --save-scene s.json",
                                     dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json s = nlohmann::json::parse(readFile(dir / "s.json"));
    EXPECT_EQ(s["water"]["enabled"], false);
    EXPECT_EQ(s["trees"]["seed"], 5);
    EXPECT_EQ(s["sky"]["zenith"], nlohmann::json::parse("[0.5, 0.25, 1.0]"));
    EXPECT_EQ(s["film"]["layers"], nlohmann::json::parse(R"(["albedo", "depth"])"));
    EXPECT_EQ(s["materials"]["wall_colour_by_type"]["house"], nlohmann::json::parse("[0.5, 0.1, 0.1]"));
    EXPECT_EQ(s["materials"]["wall_colour_by_type"]["shed"], nlohmann::json::parse("[0.2, 0.2, 0.2]"));
    EXPECT_EQ(s["lights"]["hour"], 21.0);
    EXPECT_EQ(s["terrain"]["fbm"]["octaves"], 4);
    EXPECT_EQ(s["animation"]["duration"], 2.0);
    EXPECT_EQ(s["clouds"]["type"], "stratus");
    EXPECT_EQ(s["terrain"]["dual"]["enabled"], true);
    EXPECT_EQ(s["astronomy"]["sun_from_time"], false);
}

TEST(CliOptions, BadValuesNameTheirOption) {
    const std::filesystem::path dir = testDir();
    for (const auto& [args, mention] : std::initializer_list<std::pair<std::string, std::string>>{
             {"--sky-zenith 1,2", "--sky-zenith"},
             {"--sky-ground-albedo 2,0,0", "--sky-ground-albedo: each number must be in [0, 1]"},
             {"--exr-layers albedo,colour", "--exr-layers: 'colour' is not one of albedo"},
             {"--wall-colour castle=1,0,0", "--wall-colour: need TYPE=R,G,B"},
             {"--clouds-type cirrus", "--clouds-type"},
             {"--trees-lumps 0", "--trees-lumps"},
             {"--planet-seed 3", "--planet-seed: sets a key of planet and needs --planet"}}) {
        const CommandResult r = runUrbis(kTiny + args + " --out o.png", dir);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << args << " -> " << r.err;
    }
}

TEST(CliOptions, BenchKeepsItsDefaultsUnderASceneFile) {
    const std::filesystem::path dir = testDir();
    std::ofstream(dir / "f.json") << R"({"trees": {"enabled": false}, "source": {"buildings": 6}})";
    const CommandResult r = runUrbis("bench --device cpu --repeats 1 --scene f.json --json r.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json results = nlohmann::json::parse(readFile(dir / "r.json"));
    EXPECT_EQ(results["width"], 1920) << "bench's own default, not the description's";
    EXPECT_EQ(results["height"], 1080);
    EXPECT_EQ(results["frame"]["spp"], 1);
    EXPECT_EQ(results["buildings"], 6) << "the file's";
}
