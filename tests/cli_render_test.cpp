// `urbis render` end to end: determinism across thread counts, the stats file, bad parameters.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace urbis::test;

namespace {
const std::string kSmall = "render --width 96 --height 64 --spp 2 --buildings 60 ";
}

TEST(CliRender, SamePngForOneAndTwoThreads) {
    auto dir = scratchDir("threads");
    CommandResult one = runUrbis(kSmall + "--threads 1 --out one.png", dir);
    CommandResult two = runUrbis(kSmall + "--threads 2 --out two.png", dir);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    ASSERT_EQ(two.exitCode, 0) << two.err;
    std::string a = readFile(dir / "one.png"), b = readFile(dir / "two.png");
    ASSERT_GT(a.size(), 100u);
    EXPECT_TRUE(a == b) << "the image depends on the thread count";
}

TEST(CliRender, DifferentSeedsGiveDifferentCities) {
    auto dir = scratchDir("seeds");
    ASSERT_EQ(runUrbis(kSmall + "--seed 1 --out a.png", dir).exitCode, 0);
    ASSERT_EQ(runUrbis(kSmall + "--seed 2 --out b.png", dir).exitCode, 0);
    EXPECT_NE(readFile(dir / "a.png"), readFile(dir / "b.png"));
}

TEST(CliRender, StatsFileHasTheKeysScriptsCompare) {
    auto dir = scratchDir("stats");
    CommandResult r = runUrbis(kSmall + "--stats stats.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    for (const char* key : {"triangles", "walls", "facade_cells", "bvh_nodes", "bytes_scene", "seconds_render",
                            "rays_per_second"})
        EXPECT_TRUE(stats.contains(key)) << key;
    // Procedural by default: facades are wall records, roofs (and walls too small for a facade) triangles.
    EXPECT_GT(stats["walls"].get<size_t>(), 60u * 3u);
    EXPECT_GT(stats["facade_cells"].get<size_t>(), stats["walls"].get<size_t>());
    EXPECT_GT(stats["triangles"].get<size_t>(), 60u);
    EXPECT_GT(stats["bvh_nodes"].get<size_t>(), 1u);
    EXPECT_GT(stats["rays_per_second"].get<double>(), 0.0);
    EXPECT_TRUE(stats.at("tiles_by_device").empty()) << "one device spreads no bands";
    size_t bytes = 0;
    for (const auto& [kind, n] : stats["bytes_by_kind"].items()) bytes += n.get<size_t>();
    EXPECT_EQ(bytes, stats["bytes_scene"].get<size_t>());
    EXPECT_EQ(stats["counts"]["buildings"].get<size_t>() > 0, true);
    // The streets' kinds: counted, their bytes, and the stored ones' triangles.
    for (const char* kind : {"roads", "junctions", "sidewalks", "water", "lamps"}) {
        EXPECT_GT(stats["counts"].value(kind, size_t(0)), 0u) << kind;
        EXPECT_GT(stats["bytes_by_kind"].value(kind, size_t(0)), 0u) << kind;
        if (std::string(kind) != "lamps") {
            EXPECT_GT(stats["triangles_by_kind"].value(kind, size_t(0)), 0u) << kind;
        }
    }
}

/// A bad parameter: the usage exit code, one line on stderr naming the problem, no image left behind.
void expectRejected(const std::string& args, const std::string& mention) {
    auto dir = scratchDir("bad_param");
    CommandResult r = runUrbis(args + " --out out.png", dir);
    EXPECT_EQ(r.exitCode, 2) << args << " -> " << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << args << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp")) << args;
}

TEST(CliRender, ImpossibleParametersAreRejected) {
    expectRejected("render --width 0", "--width");
    expectRejected("render --height -3", "--height");
    expectRejected("render --spp 0", "--spp");
    expectRejected("render --buildings 0", "--buildings");
    expectRejected("render --building-height-range 50:10", "--building-height-range");
    expectRejected("render --building-height-range tall", "--building-height-range");
    expectRejected("render --camera 1,2,3", "--camera");
    expectRejected("render --camera 0,0,0,0,0,0", "camera");
    expectRejected("render --camera-geo 10,48,100,0,-10", "--camera-geo");
    expectRejected("render --sun 95,0", "--sun");
    expectRejected("render --bbox 10,48,9,47", "--bbox");
}

TEST(CliRender, UnwritableOutputIsAnErrorNotAHalfFile) {
    auto dir = scratchDir("unwritable");
    CommandResult r = runUrbis(kSmall + "--out no/such/folder/x.png", dir);
    EXPECT_EQ(r.exitCode, 5);
    EXPECT_NE(r.err.find("no/such/folder/x.png"), std::string::npos) << r.err;
}
