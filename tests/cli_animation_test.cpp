// `urbis render --frames` end to end (docs/animation.md): frame N rendered alone equals frame N of a
// sequence, bit for bit, with the time of day moving (the scene relit, not rebuilt); a resumed
// sequence keeps the frames it has; bad keyframes give one line; --video through ffmpeg.
#include "cli_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    return scratchDir(std::string("animation_") + testing::UnitTest::GetInstance()->current_test_info()->name());
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// A small generated city flown around from late afternoon into the night: 2 s at 2 fps, 5 frames.
const char* kScene = R"({
  "source": {"buildings": 30, "seed": 5},
  "integrator": {"spp": 2},
  "film": {"width": 40, "height": 24},
  "animation": {
    "fps": 2,
    "camera": [
      {"time": 0, "position": [220, 120, 60], "target": [0, 10, 0], "fov": 45},
      {"time": 1, "position": [40, 140, 240], "target": [0, 10, 0], "ease": "ease_in_out"},
      {"time": 2, "position": [-200, 100, 90], "heading": 100, "pitch": -25, "fov": 55}
    ],
    "time": [
      {"time": 0, "date": "2024-06-21T19:30+02:00"},
      {"time": 2, "date": "2024-06-21T23:30+02:00"}
    ]
  }
})";

bool hasCommand(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

} // namespace

TEST(CliAnimation, FrameAloneEqualsTheSameFrameOfASequence) {
    const fs::path dir = testDir();
    write(dir / "anim.json", kScene);
    CommandResult seq = runUrbis("render --scene anim.json --frames 0:4 --threads 2 --out seq/f%02d.png", dir);
    ASSERT_EQ(seq.exitCode, 0) << seq.err;
    EXPECT_NE(seq.out.find("urbis: frames 0..4: 5 to render, 0 kept"), std::string::npos) << seq.out;
    EXPECT_NE(seq.out.find("urbis: frame 3 (4 of 5) seq/f03.png in "), std::string::npos) << seq.out;
    EXPECT_NE(seq.out.find(" left\n"), std::string::npos) << "a progress line with the time left: " << seq.out;
    CommandResult alone = runUrbis("render --scene anim.json --frames 3 --threads 1 --out alone/f%02d.png", dir);
    ASSERT_EQ(alone.exitCode, 0) << alone.err;
    const std::string a = readFile(dir / "seq/f03.png"), b = readFile(dir / "alone/f03.png");
    ASSERT_GT(a.size(), 100u);
    EXPECT_TRUE(a == b) << "frame 3 alone differs from frame 3 of the sequence";
    EXPECT_FALSE(fs::exists(dir / "alone/f02.png"));
    // The frames differ from each other: the camera moves and night falls.
    EXPECT_NE(readFile(dir / "seq/f00.png"), readFile(dir / "seq/f04.png"));
}

TEST(CliAnimation, AResumedSequenceKeepsTheFramesItHas) {
    const fs::path dir = testDir();
    write(dir / "anim.json", kScene);
    ASSERT_EQ(runUrbis("render --scene anim.json --frames 0:2 --out f%d.png", dir).exitCode, 0);
    write(dir / "f1.png", "kept");   // stands for a frame rendered before: it must not be rendered again
    CommandResult resumed = runUrbis("render --scene anim.json --frames 0:4 --out f%d.png", dir);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_NE(resumed.out.find("urbis: frames 0..4: 2 to render, 3 kept"), std::string::npos) << resumed.out;
    EXPECT_EQ(readFile(dir / "f1.png"), "kept");
    EXPECT_TRUE(fs::exists(dir / "f3.png") && fs::exists(dir / "f4.png"));
    CommandResult overwritten = runUrbis("render --scene anim.json --frames 1 --overwrite --out f%d.png", dir);
    ASSERT_EQ(overwritten.exitCode, 0) << overwritten.err;
    EXPECT_NE(readFile(dir / "f1.png"), "kept");
}

TEST(CliAnimation, BadKeyframesAndOptionsGiveOneLine) {
    const fs::path dir = testDir();
    write(dir / "unsorted.json", R"({"animation": {"camera": [
        {"time": 1, "position": [0, 50, 0], "target": [0, 0, 1]}, {"time": 0.5, "position": [9, 50, 0], "target": [0, 0, 1]}]}})");
    write(dir / "missing.json", R"({"animation": {"time": [{"date": "2024-06-21T19:30+02:00"}]}})");
    write(dir / "anim.json", kScene);
    write(dir / "still.json", R"({"film": {"width": 16, "height": 16}})");
    const std::tuple<const char*, int, const char*> cases[] = {
        {"--scene unsorted.json --frames 0:1 --out f%d.png", 1,
         "urbis: unsorted.json: animation.camera[1].time: 0.5 is not after the keyframe before's 1 (times must increase)\n"},
        {"--scene missing.json --frames 0 --out f%d.png", 1,
         "urbis: missing.json: animation.time[0].time: missing (seconds from the animation's start)\n"},
        {"--scene anim.json --frames 0:5 --out f%d.png", 2, "urbis: --frames: frame 5 is past the animation's last frame, 4\n"},
        {"--scene anim.json --frames 0:1 --out f.png", 2, "urbis: --out (film.output) with --frames: 'f.png': needs a frame field"},
        {"--scene still.json --frames 0 --out f%d.png", 2, "urbis: --frames: the scene has no animation"},
        {"--scene anim.json --frames 0 --out f%d.png --stats s.json", 2, "urbis: --stats: counts one still; not with --frames\n"},
        {"--scene anim.json --video v.mp4", 2, "urbis: --video: needs --frames\n"},
        {"--scene anim.json --frames 0 --out f%d.exr --video v.mp4", 2, "urbis: --video v.mp4: encodes .png frames"},
        {"--scene anim.json --frames 0 --out f%d.png --video v.avi", 2, "urbis: --video v.avi: expected a .mp4 or .gif file\n"},
    };
    for (const auto& [args, code, message] : cases) {
        CommandResult r = runUrbis(std::string("render ") + args, dir);
        EXPECT_EQ(r.exitCode, code) << args << " -> " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
        EXPECT_EQ(r.err.rfind(message, 0), 0u) << args << " -> " << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "f0.png"));
    // Without ffmpeg on the PATH, --video says so before any frame is rendered.
    CommandResult r = runUrbis("render --scene anim.json --frames 0 --out f%d.png --video v.mp4", dir, "PATH=/nonexistent");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("urbis: --video v.mp4: ffmpeg is not on the PATH (Debian's ffmpeg package)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "f0.png"));
}

TEST(CliAnimation, VideoEncodesTheFramesWithFfmpeg) {
    if (!hasCommand("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed (Debian's ffmpeg): --video not tested";
    const fs::path dir = testDir();
    write(dir / "anim.json", kScene);
    CommandResult r = runUrbis("render --scene anim.json --frames 0:4 --out frames/f%03d.png --video anim.mp4", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("urbis: wrote anim.mp4 (frames 0..4 at 2 fps)"), std::string::npos) << r.out;
    EXPECT_EQ(readFile(dir / "anim.mp4").substr(4, 4), "ftyp") << "an MP4 file";
    r = runUrbis("render --scene anim.json --frames 0:4 --fps 2 --out frames/f%03d.png --video anim.gif", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("0 to render, 5 kept"), std::string::npos) << "the frames were kept: " << r.out;
    EXPECT_EQ(readFile(dir / "anim.gif").substr(0, 4), "GIF8");
    EXPECT_FALSE(fs::exists(dir / "anim.gif.tmp"));
}
