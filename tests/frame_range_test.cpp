// animation/frame_range.h: --frames ranges, frame file names and the frames a resumed sequence still needs.
#include "animation/frame_range.h"

#include "cli_support.h"

#include <gtest/gtest.h>

using namespace urbis;

TEST(FrameRange, ParsesRangesSingleFramesAndOpenEnds) {
    std::string error;
    const auto range = parseFrameRange("3:7", 10, error);
    ASSERT_TRUE(range) << error;
    EXPECT_EQ(range->first, 3u);
    EXPECT_EQ(range->last, 7u);
    EXPECT_EQ(range->count(), 5u);
    EXPECT_EQ(parseFrameRange("4", 10, error)->last, 4u);
    EXPECT_EQ(parseFrameRange("4:", 10, error)->last, 9u);
    EXPECT_EQ(parseFrameRange("0:9", 10, error)->count(), 10u);
}

TEST(FrameRange, RejectsWhatIsNoRangeOfTheAnimation) {
    const std::pair<const char*, const char*> cases[] = {
        {"7:3", "'7:3': the first frame is after the last"},
        {"0:10", "frame 10 is past the animation's last frame, 9"},
        {"12", "frame 12 is past the animation's last frame, 9"},
        {"-1:3", "'-1:3': expected A:B, A or A: (frame numbers from 0)"},
        {"a:b", "'a:b': expected A:B, A or A: (frame numbers from 0)"},
        {"", "'': expected A:B, A or A: (frame numbers from 0)"},
        {"1:2:3", "'1:2:3': expected A:B, A or A: (frame numbers from 0)"},
    };
    for (const auto& [text, message] : cases) {
        std::string error;
        EXPECT_FALSE(parseFrameRange(text, 10, error)) << text;
        EXPECT_EQ(error, message);
    }
}

TEST(FrameRange, FramePathsFollowThePattern) {
    EXPECT_EQ(framePath("frames/f%04d.png", 7), "frames/f0007.png");
    EXPECT_EQ(framePath("f%04d.png", 123456), "f123456.png");
    EXPECT_EQ(framePath("shot_%d.exr", 12), "shot_12.exr");
    EXPECT_EQ(framePath("100%%/f%02d.png", 3), "100%/f03.png");
    std::string error;
    EXPECT_TRUE(isFramePattern("f%04d.png", error));
    EXPECT_FALSE(isFramePattern("f.png", error));
    EXPECT_EQ(error, "'f.png': needs a frame field, %d or %0Nd (frames/f%04d.png)");
    EXPECT_FALSE(isFramePattern("f%d_%d.png", error));
    EXPECT_EQ(error, "'f%d_%d.png': has more than one frame field (%d)");
    EXPECT_FALSE(isFramePattern("f%4d.png", error));
    EXPECT_FALSE(isFramePattern("f%s.png", error));
    EXPECT_FALSE(isFramePattern("f%0d.png", error));
    EXPECT_EQ(error, "'f%0d.png': a frame field is %d or %0Nd (N 1..9)");
}

TEST(FrameRange, AResumedSequenceRendersOnlyTheMissingFrames) {
    const auto dir = urbis::test::scratchDir("frame_range_resume");
    const std::string pattern = (dir / "f%03d.png").string();
    for (uint32_t n : {1u, 3u, 4u}) std::ofstream(framePath(pattern, n)) << "frame";
    std::ofstream(framePath(pattern, 2) + ".tmp") << "half a frame";   // a temporary is no frame
    EXPECT_EQ(framesToRender({0, 5}, pattern, false), (std::vector<uint32_t>{0, 2, 5}));
    EXPECT_EQ(framesToRender({3, 4}, pattern, false), std::vector<uint32_t>{});
    EXPECT_EQ(framesToRender({0, 5}, pattern, true), (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}
