// `mpirun -n 2 urbis render` end to end: the same PNG as one process, and a rank killed mid-frame
// ending the job non-zero with no output. Skips, saying why, without mpirun or an MPI build.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <unistd.h>

using namespace urbis::test;

namespace {

const std::string kSmall = "render --width 96 --height 64 --spp 2 --buildings 60 --threads 1 ";

/// mpirun for `ranks` ranks on however many cores there are, as root where CI runs as root; empty
/// (with the reason in `why`) where the test cannot run.
std::string mpirunPrefix(int ranks, std::string& why) {
    if (!URBIS_TESTS_MPI) {
        why = "urbis was built without MPI (libopenmpi-dev not found)";
        return "";
    }
    if (std::system("command -v mpirun >/dev/null 2>&1") != 0) {
        why = "no mpirun on PATH (openmpi-bin)";
        return "";
    }
    return "mpirun -n " + std::to_string(ranks) + " --oversubscribe" + (geteuid() == 0 ? " --allow-run-as-root" : "");
}

} // namespace

TEST(MpiRender, TwoRanksWriteThePngOfOneProcess) {
    std::string why;
    const std::string mpirun = mpirunPrefix(2, why);
    if (mpirun.empty()) GTEST_SKIP() << why;
    auto dir = scratchDir("mpi_two_ranks");
    CommandResult one = runUrbis(kSmall + "--out one.png", dir);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    CommandResult two = runUrbis(kSmall + "--out two.png --stats stats.json", dir, mpirun);
    ASSERT_EQ(two.exitCode, 0) << two.err;
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png")) << "the gathered film is not the one process's";
    // Rank 0 alone writes: one line on stdout, and the stats say which rank rendered what.
    EXPECT_EQ(std::count(two.out.begin(), two.out.end(), '\n'), 1) << two.out;
    const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    const std::vector<uint32_t> tiles = stats.at("tiles_by_rank").get<std::vector<uint32_t>>();
    ASSERT_EQ(tiles.size(), 2u);
    EXPECT_EQ(tiles[0] + tiles[1], 24u) << "96x64 in tiles of 16 (tileSizeFor)";
}

TEST(MpiRender, TwoRanksOnTheGpuWriteThePngOfOneProcess) {
    std::string why;
    const std::string mpirun = mpirunPrefix(2, why);
    if (mpirun.empty()) GTEST_SKIP() << why;
    auto dir = scratchDir("mpi_two_ranks_gpu");
    // 150x90: tiles of 32 (tileSizeFor, kGpuTileSide halved), ragged at the right and the bottom.
    const std::string gpuFrame = "render --width 150 --height 90 --spp 4 --buildings 60 --device cuda --denoise ";
    CommandResult one = runUrbis(gpuFrame + "--out one.png", dir);
    if (one.exitCode == 4) GTEST_SKIP() << "no usable GPU: " << one.err;
    ASSERT_EQ(one.exitCode, 0) << one.err;
    // Both ranks on the one GPU (local ranks 0 and 1 modulo one device).
    CommandResult two = runUrbis(gpuFrame + "--out two.png --stats stats.json", dir, mpirun);
    ASSERT_EQ(two.exitCode, 0) << two.err;
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png")) << "the ranks' GPU tiles are not the one process's frame";
    const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    EXPECT_EQ(stats.at("device"), "cuda");
    const std::vector<uint32_t> tiles = stats.at("tiles_by_rank").get<std::vector<uint32_t>>();
    ASSERT_EQ(tiles.size(), 2u);
    EXPECT_EQ(tiles[0] + tiles[1], 15u) << "150x90 in tiles of 32";
}

TEST(MpiRender, KilledRankEndsTheJobWithoutOutput) {
    std::string why;
    const std::string mpirun = mpirunPrefix(2, why);
    if (mpirun.empty()) GTEST_SKIP() << why;
    auto dir = scratchDir("mpi_killed_rank");
    // URBIS_TEST_KILL_RANK (src/cluster/mpi_world.cpp) kills rank 1 by SIGKILL at rank 0's first answer.
    CommandResult r = runUrbis(kSmall + "--out killed.png --stats killed.json", dir,
                               "URBIS_TEST_KILL_RANK=1 " + mpirun + " -x URBIS_TEST_KILL_RANK");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("signal 9"), std::string::npos) << "mpirun names the rank and its signal:\n" << r.err;
    for (const char* file : {"killed.png", "killed.png.tmp", "killed.json", "killed.json.tmp"})
        EXPECT_FALSE(std::filesystem::exists(dir / file)) << file;
}

// The photon integrators render one round a sample (each rank's light pass, then the tiles, from rank
// 0's film of the rounds before): the same PNG as one process, and the photon stats from rank 0.
TEST(MpiRender, PhotonIntegratorsOverTwoRanksWriteThePngOfOneProcess) {
    std::string why;
    const std::string mpirun = mpirunPrefix(2, why);
    if (mpirun.empty()) GTEST_SKIP() << why;
    auto dir = scratchDir("mpi_photons");
    for (const std::string integrator : {"photon-map", "photon-buffers"}) {
        const std::string frame = kSmall + "--integrator " + integrator + " --photons 4000 ";
        CommandResult one = runUrbis(frame + "--out one.png", dir);
        ASSERT_EQ(one.exitCode, 0) << one.err;
        CommandResult two = runUrbis(frame + "--out two.png --stats stats.json", dir, mpirun);
        ASSERT_EQ(two.exitCode, 0) << two.err;
        EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png")) << integrator << ": not the one process's frame";
        const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "stats.json"));
        EXPECT_GT(stats.at("photons").at("photon_rays").get<uint64_t>(), 0u) << integrator;
        const std::vector<uint32_t> tiles = stats.at("tiles_by_rank").get<std::vector<uint32_t>>();
        ASSERT_EQ(tiles.size(), 2u);
        EXPECT_EQ(tiles[0] + tiles[1], 2 * 24u) << integrator << ": 24 tiles in each of the two rounds";
    }
}

TEST(MpiRender, TwoRanksShareASequenceByFrame) {
    std::string why;
    const std::string mpirun = mpirunPrefix(2, why);
    if (mpirun.empty()) GTEST_SKIP() << why;
    auto dir = scratchDir("mpi_sequence");
    // Four frames of a camera moving over a small generated city.
    std::ofstream(dir / "anim.json") << R"({"source": {"buildings": 20, "seed": 3}, "integrator": {"spp": 1},
        "film": {"width": 32, "height": 20}, "animation": {"fps": 1, "camera": [
        {"time": 0, "position": [200, 100, 60], "target": [0, 10, 0]},
        {"time": 3, "position": [-150, 80, 120], "target": [0, 10, 0]}]}})";
    ASSERT_EQ(runUrbis("render --scene anim.json --frames 0:3 --threads 1 --out one/f%d.png", dir).exitCode, 0);
    CommandResult two = runUrbis("render --scene anim.json --frames 0:3 --threads 1 --out two/f%d.png", dir, mpirun);
    ASSERT_EQ(two.exitCode, 0) << two.err;
    for (int n = 0; n < 4; ++n) {
        const std::string name = "f" + std::to_string(n) + ".png";
        EXPECT_EQ(readFile(dir / "one" / name), readFile(dir / "two" / name)) << name << " differs from one process's";
    }
    // Each rank rendered its own two frames: every frame's progress line comes, once.
    for (int n = 0; n < 4; ++n) {
        const std::string line = "urbis: frame " + std::to_string(n) + " (";
        const size_t at = two.out.find(line);
        EXPECT_NE(at, std::string::npos) << two.out;
        EXPECT_EQ(two.out.find(line, at + 1), std::string::npos) << "frame " << n << " rendered twice:\n" << two.out;
    }
    EXPECT_NE(two.out.find("(2 of 2)"), std::string::npos) << "each rank renders two of the four frames:\n" << two.out;
}
