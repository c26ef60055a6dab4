// `urbis export` end to end: the files it writes, its bad input, and the tools that read glTF (the
// Khronos validator, Blender's importer), each skipped with a line saying why where it is absent.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <regex>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kVillage = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";
const std::string kSanFrancisco = URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf";
const std::string kSource = URBIS_SOURCE_DIR;

/// The triangles the command's line says it wrote.
size_t trianglesSaid(const CommandResult& r) {
    std::smatch m;
    return std::regex_search(r.out, m, std::regex(R"((\d+) triangles)")) ? std::stoul(m[1]) : 0;
}

/// Runs `command` (a shell line), capturing both streams; the exit code.
int shell(const std::string& command, std::string& output) {
    const fs::path log = fs::temp_directory_path() / ("urbis_export_shell_" + std::to_string(getpid()) + ".txt");
    const int status = std::system((command + " >'" + log.string() + "' 2>&1").c_str());
    output = readFile(log);
    fs::remove(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Runs the Khronos validator on `file`; skips (returning false) where node or its module is missing.
bool validatorReportsNoErrors(const fs::path& file, std::string& report) {
    const int rc = shell("NODE_PATH=\"$(npm root -g 2>/dev/null)\" node '" + kSource + "/scripts/gltf_validate.js' '" +
                             file.string() + "'",
                         report);
    return rc == 0;
}

bool haveValidator() {
    std::string out;
    return shell("NODE_PATH=\"$(npm root -g 2>/dev/null)\" node -e \"require('gltf-validator')\"", out) == 0;
}

} // namespace

TEST(ExportCli, VillageGlbIsWrittenWholeAndReadsBack) {
    const fs::path dir = scratchDir("export_cli_glb");
    CommandResult r = runUrbis("export --osm '" + kVillage + "' --out village.glb", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote village.glb"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir / "village.glb.tmp"));
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, (dir / "village.glb").string())) << err;
    size_t triangles = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) triangles += model.accessors[size_t(p.indices)].count / 3;
    EXPECT_EQ(triangles, trianglesSaid(r));
    EXPECT_EQ(model.asset.extras.Get("lod").Get<std::string>(), "facades");
}

TEST(ExportCli, MassModelIsLighterThanFacades) {
    const fs::path dir = scratchDir("export_cli_lod");
    CommandResult facades = runUrbis("export --buildings 20 --no-streets --out f.glb", dir);
    CommandResult mass = runUrbis("export --buildings 20 --no-streets --lod mass --out m.glb", dir);
    ASSERT_EQ(facades.exitCode, 0) << facades.err;
    ASSERT_EQ(mass.exitCode, 0) << mass.err;
    // Twelve triangles a box against hundreds a facade: at least ten times fewer.
    EXPECT_LT(trianglesSaid(mass) * 10, trianglesSaid(facades)) << mass.out << facades.out;
}

TEST(ExportCli, TilesWriteAFileEachAndAnIndex) {
    const fs::path dir = scratchDir("export_cli_tiles");
    CommandResult whole = runUrbis("export --osm '" + kVillage + "' --out whole.obj", dir);
    CommandResult tiled = runUrbis("export --osm '" + kVillage + "' --tiles 80 --out city.glb", dir);
    ASSERT_EQ(tiled.exitCode, 0) << tiled.err;
    const nlohmann::json index = nlohmann::json::parse(readFile(dir / "city.tiles.json"));
    EXPECT_EQ(index["tile_size"].get<double>(), 80.0);
    EXPECT_TRUE(index["extras"].contains("origin"));
    ASSERT_GT(index["tiles"].size(), 3u);
    size_t triangles = 0;
    for (const auto& tile : index["tiles"]) {
        const std::string file = tile["file"];
        EXPECT_EQ(file, "city_" + std::to_string(tile["x"].get<int>()) + "_" + std::to_string(tile["z"].get<int>()) + ".glb");
        EXPECT_TRUE(fs::exists(dir / file)) << file;
        triangles += tile["triangles"].get<size_t>();
    }
    EXPECT_EQ(triangles, trianglesSaid(whole)) << "the tiles hold every triangle of the whole export, once";
    EXPECT_FALSE(fs::exists(dir / "city.glb")) << "with --tiles only the tiles and the index";
}

TEST(ExportCli, BadOutputsGiveOneLineAndNoFile) {
    const fs::path dir = scratchDir("export_cli_bad");
    std::ofstream(dir / "a_file") << "x";
    struct Case {
        std::string args;
        int exitCode;
        std::string names;   ///< what the message must name
    } cases[] = {
        {"--out city.fbx", 2, "city.fbx"},
        {"--out city.glb --tiles 0", 2, "--tiles"},
        {"--out city.glb --tiles -5", 2, "--tiles"},
        {"--out missing_folder/city.glb", 5, "missing_folder"},
        {"--out a_file/city.glb", 5, "a_file"},
        {"--out city.glb --lod bricks", 2, "--lod"},
    };
    for (const Case& c : cases) {
        CommandResult r = runUrbis("export --buildings 4 --no-streets " + c.args, dir);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << ": " << r.err;
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            EXPECT_TRUE(name == "a_file" || name == "stdout.txt" || name == "stderr.txt") << c.args << " left " << name;
        }
    }
}

TEST(ExportTools, KhronosValidatorFindsNoErrors) {
    if (!haveValidator())
        GTEST_SKIP() << "node or npm's gltf-validator is not installed (npm install -g gltf-validator): validator not run";
    const fs::path dir = scratchDir("export_validator");
    std::vector<std::pair<std::string, std::string>> exports = {
        {"village.glb", "--osm '" + kVillage + "' --time 2024-06-21T21:30+02:00"},
        {"village.gltf", "--osm '" + kVillage + "' --lod mass"},
        {"generated.glb", "--buildings 40"},
    };
    // Four blocks of the Embarcadero: the whole extract's twin is 47 million triangles.
    if (fs::exists(kSanFrancisco))
        exports.push_back({"sf.glb", "--osm '" + kSanFrancisco + "' --bbox -122.398,37.792,-122.393,37.796 --lod mass"});
    else std::printf("[ SKIPPED  ] San Francisco's export: %s not found (the shared extracts)\n", kSanFrancisco.c_str());
    for (const auto& [file, args] : exports) {
        CommandResult r = runUrbis("export " + args + " --out " + file, dir);
        ASSERT_EQ(r.exitCode, 0) << file << ": " << r.err;
        std::string report;
        EXPECT_TRUE(validatorReportsNoErrors(dir / file, report)) << file << ": " << report;
    }
}

TEST(ExportTools, BlenderImportsGlbAndObj) {
    std::string version;
    if (shell("blender --version", version) != 0)
        GTEST_SKIP() << "blender is not installed (Debian's blender): the import check not run";
    const fs::path dir = scratchDir("export_blender");
    for (const char* file : {"village.glb", "village.obj"}) {
        CommandResult r = runUrbis("export --osm '" + kVillage + "' --out " + file, dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::string log;
        const int rc = shell("blender -b --factory-startup --python-exit-code 1 --python '" + kSource +
                                 "/bench/cycles/import_check.py' -- '" + (dir / file).string() + "'",
                             log);
        ASSERT_EQ(rc, 0) << log;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(import_check: (\d+) meshes, \d+ materials, (\d+) cameras, \d+ lights, (\d+) triangles)")))
            << log;
        std::smatch nodes;
        ASSERT_TRUE(std::regex_search(r.out, nodes, std::regex(R"((\d+) nodes)")));
        EXPECT_EQ(m[1].str(), nodes[1].str()) << file << ": a Blender object per node";
        EXPECT_EQ(std::stoul(m[3]), trianglesSaid(r)) << file;
        EXPECT_EQ(m[2].str(), std::string(file).ends_with(".glb") ? "1" : "0") << file << ": the camera comes with glTF";
    }
}
