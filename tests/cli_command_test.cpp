// The urbis command's behaviour end to end: exit codes, outputs, memory, camera checks, messages.
#include "cli_support.h"
#include "film/denoise_filter.h"
#include "film/film_output.h"

#include <gtest/gtest.h>

#include <chrono>
#include <regex>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kTiny = "render --width 32 --height 32 --spp 1 --buildings 20 ";

int lines(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

/// A failing command: `code`, one line on stderr holding every one of `mentions`, no out.png left.
void expectFailure(const std::string& args, int code, std::initializer_list<std::string> mentions) {
    // One folder per test: ctest runs the tests of this file in parallel processes.
    auto dir = scratchDir(std::string("failure_") + testing::UnitTest::GetInstance()->current_test_info()->name());
    CommandResult r = runUrbis(args, dir);
    EXPECT_EQ(r.exitCode, code) << args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << ": not one line: " << r.err;
    for (const std::string& m : mentions) EXPECT_NE(r.err.find(m), std::string::npos) << args << " -> " << r.err;
    for (const char* name : {"out.png", "out.png.tmp", "urbis.png", "s.json"})
        EXPECT_FALSE(fs::exists(dir / name)) << name << " left behind by " << args;
}

} // namespace

TEST(CliCommand, VersionIsTheProjectVersion) {
    CommandResult r = runUrbis("--version", scratchDir("version"));
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "urbis 0.1\n");
}

TEST(CliCommand, HelpListsTheExitCodes) {
    CommandResult r = runUrbis("--help", scratchDir("help"));
    EXPECT_EQ(r.exitCode, 0);
    for (const char* line : {"Exit codes:", "2  usage", "3  out of memory", "5  an output file"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line;
}

TEST(CliCommand, UnknownSubcommandIsNamed) {
    expectFailure("rendr", 2, {"unknown subcommand 'rendr'", "render, inspect, bench"});
}

TEST(CliCommand, ParserAndOptionValueErrorsShareTheUsageCode) {
    expectFailure(kTiny + "--no-such-option", 2, {"--no-such-option"});
    expectFailure(kTiny + "--width 0", 2, {"--width"});
    expectFailure(kTiny + "--sun 100,0", 2, {"--sun"});
    expectFailure(kTiny + "--camera 1,2", 2, {"--camera"});
    expectFailure(kTiny + "--geometry walls=glass", 2, {"--geometry"});
    expectFailure(kTiny + "--wall-tiles 4y4", 2, {"--wall-tiles"});
    for (const char* size : {"12Q", "0", "-5G", "G", "1e30"})
        expectFailure(kTiny + "--max-memory " + size, 2, {"--max-memory", size});
}

TEST(CliCommand, EachKindOfFailureHasItsCode) {
    expectFailure(kTiny + "--osm missing.osm.pbf", 1, {"missing.osm.pbf"});
    expectFailure(kTiny + "--out no/such/folder/x.png", 5, {"no/such/folder/x.png"});
    auto dir = scratchDir("device");
    CommandResult r = runUrbis(kTiny + "--device cuda --out out.png", dir);
    if (r.exitCode != 0) {
        EXPECT_EQ(r.exitCode, 4) << "no usable GPU is a device failure: " << r.err;
    }
}

TEST(CliCommand, TheFormatFollowsTheExtension) {
    for (const char* name : {"out.tiff", "out.hdr", "out.jpg", "out"})
        expectFailure(kTiny + "--out " + name, 2, {"--out", name});
    expectFailure(kTiny + "--out out.png --stats s.txt", 2, {"--stats", ".txt"});
    expectFailure(kTiny + "--out out.png --stats out.png", 2, {"--stats", "out.png"});
    expectFailure("bench --device cpu --buildings 20 --width 8 --height 8 --json b.csv", 2, {"--json", ".csv"});
    auto dir = scratchDir("upper_case_png");
    EXPECT_EQ(runUrbis(kTiny + "--out OUT.PNG", dir).exitCode, 0);
    EXPECT_EQ(readFile(dir / "OUT.PNG").substr(1, 3), "PNG");
}

TEST(CliCommand, AnImageTooLargeForTheMemoryIsRefusedUpFront) {
    const auto start = std::chrono::steady_clock::now();
    expectFailure("render --width 16384 --height 16384 --max-memory 2G --out out.png", 3,
                  {"16384x16384", "5100322816 bytes", "2147483648 bytes"});
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    expectFailure("bench --device cpu --width 16384 --height 16384 --max-memory 512M", 3, {"536870912 bytes"});
    auto dir = scratchDir("fits");
    EXPECT_EQ(runUrbis(kTiny + "--max-memory 512M", dir).exitCode, 0);
}

// --denoise adds its buffers (guide and two signals a pixel) to what the image needs up front.
TEST(CliCommand, TheDenoisersBuffersCountInTheImagesMemory) {
    const size_t plain = urbis::hostFilmBytes(4096, 4096), denoised = urbis::hostFilmBytes(4096, 4096, false, true);
    EXPECT_GE(denoised - plain, size_t(4096) * 4096 * urbis::kDenoiseBytesPerPixel);
    ASSERT_GT(denoised, plain);
    const std::string limit = std::to_string((plain + denoised) / 2);
    expectFailure("render --width 4096 --height 4096 --denoise --max-memory " + limit + " --out out.png", 3,
                  {"4096x4096", std::to_string(denoised) + " bytes"});
}

TEST(CliCommand, TheTriangleTwinRespectsMaxMemory) {
    expectFailure(kTiny + "--geometry walls=triangles --max-memory 1M --out out.png", 3, {"triangle twin", "--geometry"});
}

TEST(CliCommand, CameraUnderTheGroundOrFarAwayWarnsOrFailsWithStrict) {
    auto dir = scratchDir("camera_warnings");
    struct Case {
        std::string camera, mention;
    };
    for (const Case& c : {Case{"0,-5,0,10,0,10", "under the ground"}, Case{"90000,50,0,0,0,0", "farther than its extent"}}) {
        CommandResult warned = runUrbis(kTiny + "--camera " + c.camera + " --out out.png", dir);
        EXPECT_EQ(warned.exitCode, 0) << warned.err;
        EXPECT_EQ(lines(warned.err), 1) << warned.err;
        EXPECT_NE(warned.err.find("urbis: warning: "), std::string::npos) << warned.err;
        EXPECT_NE(warned.err.find(c.mention), std::string::npos) << warned.err;
        fs::remove(dir / "out.png");
        expectFailure(kTiny + "--strict --camera " + c.camera + " --out out.png", 2, {c.mention, "--strict"});
    }
    CommandResult framed = runUrbis(kTiny + "--strict --out out.png", dir);
    EXPECT_EQ(framed.exitCode, 0) << framed.err;
    EXPECT_EQ(framed.err, "") << "the default camera needs no warning";
}

TEST(CliCommand, RenderSaysWhatItWroteAndNothingElse) {
    auto dir = scratchDir("wrote");
    CommandResult r = runUrbis(kTiny + "--out out.png --stats s.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::regex_match(r.out, std::regex(R"(urbis: wrote out\.png \(32x32, 1 spp, (cpu|cuda)\) and s\.json in [0-9.]+ s\n)")))
        << r.out;
    EXPECT_TRUE(fs::exists(dir / "out.png") && fs::exists(dir / "s.json"));
    // The device is said only when asked: with --verbose, or --device cuda.
    EXPECT_EQ(r.err.find("rendering on"), std::string::npos) << r.err;
    CommandResult verbose = runUrbis(kTiny + "--verbose --out out.png", dir);
    ASSERT_EQ(verbose.exitCode, 0) << verbose.err;
    EXPECT_NE(verbose.err.find("urbis: rendering on"), std::string::npos) << verbose.err;
}
