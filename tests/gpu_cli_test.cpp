// `urbis render --device` and `urbis bench` end to end, with and without a usable GPU.
#include "cli_support.h"
#include "gpu_test_support.h"

#include <nlohmann/json.hpp>

using namespace urbis::test;

namespace {
const std::string kSmall = "render --width 64 --height 48 --spp 2 --buildings 40 ";

size_t lineCount(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }
} // namespace

TEST(GpuCli, DeviceCudaRendersOnTheGpuOrFailsInOneLine) {
    auto dir = scratchDir("gpu_cuda");
    CommandResult r = runUrbis(kSmall + "--device cuda --stats stats.json", dir);
    if (!urbis::probeGpu().available) {
        EXPECT_EQ(r.exitCode, 4) << "a device failure";
        EXPECT_EQ(lineCount(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find("--device cuda"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "urbis.png"));
        return;
    }
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("(cuda)"), std::string::npos) << r.err;
    auto stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    EXPECT_EQ(stats["device"], "cuda");
    EXPECT_FALSE(stats["device_name"].get<std::string>().empty());
    EXPECT_GT(stats["bytes_device"]["total"].get<size_t>(), stats["bytes_device"]["bvh"].get<size_t>());
    EXPECT_GT(stats["rays_per_second"].get<double>(), 0.0);
}

TEST(GpuCli, DeviceAutoAlwaysRendersAndSaysWhereWhenVerbose) {
    auto dir = scratchDir("gpu_auto");
    CommandResult quiet = runUrbis(kSmall + "--device auto", dir);
    ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_EQ(quiet.err.find("rendering on"), std::string::npos) << "said without --verbose: " << quiet.err;
    CommandResult r = runUrbis(kSmall + "--device auto --verbose --stats stats.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_GT(readFile(dir / "urbis.png").size(), 100u);
    auto stats = nlohmann::json::parse(readFile(dir / "stats.json"));
    bool gpu = urbis::probeGpu().available;
    EXPECT_EQ(stats["device"], gpu ? "cuda" : "cpu");
    EXPECT_NE(r.err.find(gpu ? "(cuda)" : "rendering on the CPU"), std::string::npos) << r.err;
}

TEST(GpuCli, CpuAndCudaTraceNearlyTheSamePaths) {
    URBIS_SKIP_WITHOUT_GPU();
    auto dir = scratchDir("gpu_png");
    ASSERT_EQ(runUrbis(kSmall + "--device cpu --out cpu.png --stats cpu.json", dir).exitCode, 0);
    ASSERT_EQ(runUrbis(kSmall + "--device cuda --out gpu.png --stats gpu.json", dir).exitCode, 0);
    auto cpu = nlohmann::json::parse(readFile(dir / "cpu.json"));
    auto gpu = nlohmann::json::parse(readFile(dir / "gpu.json"));
    // Traversal is bit-equal (-fmad=false), shading on the GPU uses the hardware's approximations
    // (the precision policy, docs/architecture.md): paths take the same turns but for a few, so nearly the same ray count.
    EXPECT_NEAR(cpu["rays"].get<double>(), gpu["rays"].get<double>(), 1e-3 * cpu["rays"].get<double>());
    EXPECT_GT(readFile(dir / "gpu.png").size(), 100u);
}

TEST(GpuCli, BenchPrintsATableAndJson) {
    auto dir = scratchDir("gpu_bench");
    bool gpu = urbis::probeGpu().available;
    std::string device = gpu ? "cuda" : "cpu";
    CommandResult r = runUrbis("bench --device " + device +
                                   " --buildings 40 --width 64 --height 48 --repeats 2 --warmup 1 --json b.json",
                               dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("primary rays"), std::string::npos) << r.out;
    auto json = nlohmann::json::parse(readFile(dir / "b.json"));
    EXPECT_EQ(json["device"], device);
    EXPECT_EQ(json["rays"]["primary"]["count"].get<size_t>(), 64u * 48u);
    EXPECT_GT(json["rays"]["primary"]["rays_per_second"].get<double>(), 0.0);
    EXPECT_GT(json["frame"]["median_ms"].get<double>(), 0.0);
}

TEST(GpuCli, BenchOnCudaWithoutAGpuFailsInOneLine) {
    if (urbis::probeGpu().available) GTEST_SKIP() << "a GPU is present";
    auto dir = scratchDir("gpu_bench_none");
    CommandResult r = runUrbis("bench --device cuda --buildings 10 --width 8 --height 8", dir);
    EXPECT_EQ(r.exitCode, 4) << "a device failure";
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
}
