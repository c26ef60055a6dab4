// `urbis render --out FILE.exr` end to end: the AOV layers come with an EXR, errors name the file.
#include "cli_support.h"
#include "film_exr_read.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace urbis::test;

namespace {
const std::string kTiny = "render --width 32 --height 24 --spp 2 --buildings 20 --device cpu ";
}

TEST(FilmCli, ExrHasEveryLayer) {
    auto dir = scratchDir("film_cli_exr");
    CommandResult r = runUrbis(kTiny + "--out city.exr", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote city.exr"), std::string::npos) << r.out;
    const ExrRead exr = readExr((dir / "city.exr").string());
    EXPECT_EQ(exr.width, 32);
    EXPECT_EQ(exr.height, 24);
    for (const char* name : {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z",
                             "depth.Z", "position.X", "position.Y", "position.Z", "id.object", "id.part", "samples"})
        EXPECT_EQ(exr.types.count(name), 1u) << name;
    for (uint32_t n : exr.uints.at("samples")) EXPECT_EQ(n, 2u);
    EXPECT_EQ(exr.types.at("R"), Imf::HALF);
    EXPECT_FALSE(std::filesystem::exists(dir / "city.exr.tmp"));
    ASSERT_EQ(runUrbis(kTiny + "--exr-float --out float.exr", dir).exitCode, 0);
    EXPECT_EQ(readExr((dir / "float.exr").string()).types.at("R"), Imf::FLOAT);
}

TEST(FilmCli, ExrInAMissingFolderIsOneLine) {
    auto dir = scratchDir("film_cli_missing");
    CommandResult r = runUrbis(kTiny + "--out no/such/folder/x.exr", dir);
    EXPECT_EQ(r.exitCode, 5);
    EXPECT_NE(r.err.find("no/such/folder/x.exr"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// --denoise runs the AOV pass for a PNG too and filters the film before it is written: the EXR's
// colour changes, its sample counts and ids do not; the stats give the filter's time.
TEST(FilmCli, DenoiseFiltersTheWrittenFilm) {
    auto dir = scratchDir("film_cli_denoise");
    ASSERT_EQ(runUrbis(kTiny + "--exr-float --out noisy.exr", dir).exitCode, 0);
    CommandResult r = runUrbis(kTiny + "--exr-float --denoise --out clean.exr --stats stats.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ExrRead noisy = readExr((dir / "noisy.exr").string()), clean = readExr((dir / "clean.exr").string());
    EXPECT_NE(noisy.floats.at("R"), clean.floats.at("R"));
    EXPECT_EQ(noisy.uints.at("id.object"), clean.uints.at("id.object"));
    EXPECT_EQ(noisy.uints.at("samples"), clean.uints.at("samples"));
    EXPECT_NE(readFile((dir / "stats.json").string()).find("\"denoise\""), std::string::npos);
    EXPECT_EQ(runUrbis(kTiny + "--denoise --out clean.png", dir).exitCode, 0);
}
