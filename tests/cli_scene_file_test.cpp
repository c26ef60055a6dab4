// `urbis render --scene` and `--save-scene` end to end: the round trip gives the same image, the
// command line overrides the file, bad scene files give one line and exit 1.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kSmall = "render --width 48 --height 32 --spp 2 --buildings 40 ";

std::filesystem::path testDir() {
    return scratchDir(std::string("scene_file_") + testing::UnitTest::GetInstance()->current_test_info()->name());
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

} // namespace

TEST(CliSceneFile, SavedSceneRendersTheSameImage) {
    const fs::path dir = testDir();
    CommandResult first = runUrbis(kSmall + "--seed 3 --sun 25,200 --exposure 0.5 --geometry walls=triangles "
                                            "--camera 150,90,260,0,10,0 --fov 40 --out a.png --save-scene a.json",
                                   dir);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    ASSERT_TRUE(fs::exists(dir / "a.json"));
    EXPECT_NE(first.out.find(" and a.json "), std::string::npos) << first.out;
    CommandResult second = runUrbis("render --scene a.json --out b.png", dir);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    const std::string a = readFile(dir / "a.png"), b = readFile(dir / "b.png");
    ASSERT_GT(a.size(), 100u);
    EXPECT_TRUE(a == b) << "rendering the saved scene gave another image";
    // Saving the scene that a scene file amounts to gives the same file back.
    ASSERT_EQ(runUrbis("render --scene a.json --save-scene c.json --out a.png", dir).exitCode, 0);
    EXPECT_EQ(readFile(dir / "a.json"), readFile(dir / "c.json"));
}

TEST(CliSceneFile, TheCommandLineOverridesTheFile) {
    const fs::path dir = testDir();
    write(dir / "s.json", R"({"film": {"width": 40, "height": 30, "output": "file.png"},
                              "integrator": {"spp": 1}, "source": {"buildings": 30}})");
    ASSERT_EQ(runUrbis("render --scene s.json --width 56 --save-scene saved.json", dir).exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "file.png")) << "film.output of the file";
    const nlohmann::json saved = nlohmann::json::parse(readFile(dir / "saved.json"));
    EXPECT_EQ(saved["film"]["width"], 56) << "given on the command line";
    EXPECT_EQ(saved["film"]["height"], 30) << "the file's, not the command's default";
    EXPECT_EQ(saved["integrator"]["spp"], 1);
    EXPECT_EQ(saved["source"]["buildings"], 30);
    // The same image as the command line that says it all.
    ASSERT_EQ(runUrbis("render --width 56 --height 30 --spp 1 --buildings 30 --out direct.png", dir).exitCode, 0);
    EXPECT_TRUE(readFile(dir / "file.png") == readFile(dir / "direct.png"));
}

TEST(CliSceneFile, SavedSceneOfTheDefaultCommandHasEveryKey) {
    const fs::path dir = testDir();
    ASSERT_EQ(runUrbis("render --width 16 --height 16 --spp 1 --buildings 5 --save-scene s.json", dir).exitCode, 0);
    const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "s.json"));
    size_t keys = 0;
    for (const auto& [section, fields] : scene.items()) {
        if (section == "planet" && fields.is_null()) {  // no planet: the city
            ++keys;
            continue;
        }
        ASSERT_TRUE(fields.is_object()) << section;
        for (const auto& [key, value] : fields.items()) keys += 1 + (value.is_object() ? value.size() : 0);
    }
    for (const char* section : {"source", "camera", "sun", "astronomy", "sky", "materials", "geometry", "integrator", "film", "terrain", "water", "trees", "clouds"})
        EXPECT_TRUE(scene.contains(section)) << section;
    EXPECT_EQ(keys, 150u) << "every key with its value (docs/scene_files.md)";
    EXPECT_EQ(scene["integrator"]["rr_survival"], 0.95);
    EXPECT_EQ(scene["camera"]["position"], nullptr);
}

TEST(CliSceneFile, BadSceneFilesGiveOneLineAndExitOne) {
    const fs::path dir = testDir();
    write(dir / "malformed.json", "{\"film\": {\"width\": 10,,}}");
    write(dir / "unknown.json", R"({"film": {"widht": 10}})");
    write(dir / "type.json", R"({"camera": {"fov": "wide"}})");
    write(dir / "range.json", R"({"film": {"width": 0}})");
    fs::create_directories(dir / "folder.json");
    const std::pair<const char*, const char*> cases[] = {
        {"malformed.json", "malformed.json: malformed JSON at line 1, column "},
        {"unknown.json", "unknown.json: film.widht: unknown key"},
        {"type.json", "type.json: camera.fov: expected a number"},
        {"range.json", "range.json: film.width: 0 is out of range 1..65536"},
        {"none.json", "none.json: cannot open the scene file"},
        {"folder.json", "folder.json: cannot read the scene file (a folder)"},
    };
    for (const auto& [file, message] : cases) {
        CommandResult r = runUrbis(std::string("render --scene ") + file + " --out out.png", dir);
        EXPECT_EQ(r.exitCode, 1) << file << " -> " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
        EXPECT_NE(r.err.find(std::string("urbis: ") + message), std::string::npos) << file << " -> " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out.png")) << file;
    }
}

TEST(CliSceneFile, OsmPathIsRelativeToTheSceneFile) {
    const fs::path example = fs::path(URBIS_EXAMPLES) / "roof_shapes.osm";
    const fs::path dir = testDir();
    fs::create_directories(dir / "scenes");
    fs::copy_file(example, dir / "roof_shapes.osm");
    write(dir / "scenes" / "s.json", R"({"source": {"osm": "../roof_shapes.osm"},
        "film": {"width": 32, "height": 24, "output": "out.png"}, "integrator": {"spp": 1}})");
    CommandResult r = runUrbis("render --scene scenes/s.json --stats stats.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    EXPECT_GT(stats["counts"]["buildings"].get<size_t>(), 0u);
    EXPECT_EQ(stats["scene"]["source"]["osm"], "roof_shapes.osm") << "the file's folder joined and normalised";
}

TEST(CliSceneFile, StatsReportPeakMemory) {
    const fs::path dir = testDir();
    ASSERT_EQ(runUrbis(kSmall + "--device cpu --stats stats.json", dir).exitCode, 0);
    const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    EXPECT_GT(stats["peak_host_bytes"].get<size_t>(), size_t(1) << 20) << "a process holds more than a MiB";
    EXPECT_TRUE(stats["peak_device_bytes"].is_null()) << "the CPU rendered";
    EXPECT_GT(stats["resident_host_bytes"].get<size_t>(), 0u);
    EXPECT_LE(stats["resident_host_bytes"].get<size_t>(), stats["peak_host_bytes"].get<size_t>());
}

TEST(CliSceneFile, SaveSceneOutputIsChecked) {
    const fs::path dir = testDir();
    CommandResult r = runUrbis(kSmall + "--save-scene scene.txt", dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--save-scene"), std::string::npos) << r.err;
    r = runUrbis(kSmall + "--stats s.json --save-scene s.json", dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = runUrbis(kSmall + "--camera 1,2,3,4,5,6 --camera-geo 1,2,3,4,5", dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST(CliSceneFile, TheDocumentedExampleRendersAndOverridesChangeTheImage) {
    const fs::path dir = testDir();
    const std::string small = " --width 48 --height 27 --spp 1 --buildings 30";
    CommandResult example = runUrbis("render --scene '" URBIS_EXAMPLES "/scene.json'" + small + " --out example.png", dir);
    ASSERT_EQ(example.exitCode, 0) << example.err;
    write(dir / "plain.json", "{}");
    write(dir / "red.json", R"({"materials": {"wall_colour_by_type": {"generic": [0.8, 0.1, 0.1],
        "residential": [0.8, 0.1, 0.1], "apartments": [0.8, 0.1, 0.1], "house": [0.8, 0.1, 0.1],
        "commercial": [0.8, 0.1, 0.1], "office": [0.8, 0.1, 0.1], "retail": [0.8, 0.1, 0.1]}}})");
    write(dir / "ground.json", R"({"materials": {"ground": {"albedo": [0.6, 0.6, 0.6]}}})");
    for (const char* name : {"plain", "red", "ground"})
        ASSERT_EQ(runUrbis(std::string("render --scene ") + name + ".json" + small + " --out " + name + ".png", dir).exitCode, 0);
    const std::string plain = readFile(dir / "plain.png");
    EXPECT_FALSE(plain == readFile(dir / "red.png")) << "wall colours by type left the image as it was";
    EXPECT_FALSE(plain == readFile(dir / "ground.png")) << "the ground's albedo left the image as it was";
}

TEST(CliSceneFile, BenchTakesSceneFilesToo) {
    const fs::path dir = testDir();
    const std::string bench = "bench --device cpu --repeats 1 --buildings 12 --width 24 --height 16 ";
    CommandResult saved = runUrbis(bench + "--save-scene b.json", dir);
    ASSERT_EQ(saved.exitCode, 0) << saved.err;
    const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "b.json"));
    EXPECT_EQ(scene["integrator"]["spp"], 1) << "bench's own default";
    EXPECT_EQ(scene["film"]["width"], 24);
    CommandResult fromFile = runUrbis("bench --device cpu --repeats 1 --scene b.json --spp 2 --json r.json", dir);
    ASSERT_EQ(fromFile.exitCode, 0) << fromFile.err;
    const nlohmann::json results = nlohmann::json::parse(readFile(dir / "r.json"));
    EXPECT_EQ(results["width"], 24);
    EXPECT_EQ(results["buildings"], 12);
    EXPECT_EQ(results["frame"]["spp"], 2) << "the command line over the file";
}
