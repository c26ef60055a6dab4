// Inputs the fuzzer (docs/fuzzing.md) once crashed urbis on, each in tests/fuzz_crashers/: each must
// now import and mesh, or end in a clean InputError, through the library and the real command.
#include "citygen/city_mesher.h"
#include "cli_support.h"
#include "base/input_error.h"
#include "osm/osm_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace urbis;
using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const fs::path kCrashers = URBIS_FUZZ_CRASHERS;

/// The crashers: .osm and .osm.pbf files (the format comes from the name).
std::vector<fs::path> crashers() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kCrashers))
        if (const std::string name = entry.path().filename().string(); name.ends_with(".osm") || name.ends_with(".osm.pbf"))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST(FuzzCrashers, ImportAndMeshOrFailCleanly) {
    const std::vector<fs::path> files = crashers();
    ASSERT_FALSE(files.empty()) << kCrashers;
    for (const fs::path& file : files) {
        try {
            const CityModel city = importOsm(file.string(), {});
            const CityMesh mesh = meshCity(city);
            EXPECT_GT(mesh.mesh.size() + mesh.walls.size(), 0u) << file;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << e.what();
        }
    }
}

TEST(FuzzCrashers, TheCommandExitsCleanly) {
    for (const fs::path& file : crashers()) {
        const fs::path dir = scratchDir("fuzz_crasher");
        const CommandResult r = runUrbis("render --osm '" + file.string() + "' --width 16 --height 16 --spp 1", dir);
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1) << file << " exit " << r.exitCode << ": " << r.err;
        EXPECT_EQ(fs::exists(dir / "urbis.png"), r.exitCode == 0) << file;
    }
}
