// The pieces of an MPI render that need no MPI: the tiles cover the frame once, a film's rectangle
// survives packing bit for bit, tiles rendered apart make the film of one render, and frames
// spread over ranks come once each.
#include "cluster/film_tiles.h"
#include "cluster/frame_spread.h"
#include "cluster/tile_grid.h"
#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <tuple>

using namespace urbis;

TEST(ClusterTiles, CoverEveryPixelOnce) {
    for (auto [w, h, side] : {std::tuple{96u, 64u, 16u}, {100u, 37u, 32u}, {1u, 1u, 64u}, {130u, 65u, 64u}}) {
        std::vector<int> covered(size_t(w) * h, 0);
        for (const PixelRect& t : tilesOf(w, h, side)) {
            EXPECT_LE(t.width(), side);
            EXPECT_LE(t.height(), side);
            for (uint32_t y = t.y0; y < t.y1; ++y)
                for (uint32_t x = t.x0; x < t.x1; ++x) ++covered[size_t(y) * w + x];
        }
        for (int c : covered) ASSERT_EQ(c, 1) << w << "x" << h << " in tiles of " << side;
    }
    EXPECT_TRUE(tilesOf(0, 10, 16).empty());
    EXPECT_THROW(tilesOf(10, 10, 0), std::invalid_argument);
}

TEST(ClusterTiles, SizeLeavesEveryRankSeveralTiles) {
    EXPECT_EQ(tileSizeFor(1920, 1080, 16), 64u);   // 510 tiles
    EXPECT_EQ(tileSizeFor(96, 64, 2), 16u);        // 64: 2 tiles, 32: 6, 16: 24
    EXPECT_EQ(tileSizeFor(8, 8, 4), 16u);          // never below 16 (one TBB task)
    // GPU ranks take up to kGpuTileSide: 256, about one wave of blocks on an H200.
    EXPECT_EQ(tileSizeFor(1920, 1080, 8, kGpuTileSide), 256u);    // 40 tiles
    EXPECT_EQ(tileSizeFor(1920, 1080, 16, kGpuTileSide), 128u);   // 256: 40 tiles, 128: 135
    EXPECT_EQ(tileSizeFor(150, 90, 2, kGpuTileSide), 32u);        // 64: 6 tiles, 32: 15
}

// The bands of GPU streams: whole rows, one after the other down the frame, on the render kernel's
// 16-row blocks, no smaller than 16 rows but at the frame's edge, shrinking (guided self-scheduling).
TEST(ClusterTiles, GpuBandsCoverTheFrameInShrinkingRunsOfWholeBlocks) {
    for (auto [w, h, streams] : {std::tuple{1920u, 1080u, 8}, {3840u, 2160u, 32}, {150u, 90u, 8}, {7u, 5u, 4}, {64u, 16u, 1}}) {
        const std::vector<PixelRect> bands = bandsOf(w, h, streams);
        ASSERT_FALSE(bands.empty());
        uint32_t y = 0;
        for (size_t i = 0; i < bands.size(); ++i) {
            const PixelRect& b = bands[i];
            EXPECT_EQ(b.x0, 0u);
            EXPECT_EQ(b.x1, w);
            EXPECT_EQ(b.y0, y) << "band " << i << " does not follow the one before";
            EXPECT_EQ(b.y0 % 16, 0u) << "band " << i << " starts inside a block";
            if (b.y1 < h) {
                EXPECT_GE(b.height(), 16u);
            }
            if (i > 0) {
                EXPECT_LE(b.height(), bands[i - 1].height()) << "band " << i << " grew";
            }
            y = b.y1;
        }
        EXPECT_EQ(y, h) << w << "x" << h;
    }
    // 1080 rows over 8 streams: 1080 / 8 = 135 -> 128 rows first, 16 at the end.
    const std::vector<PixelRect> bands = bandsOf(1920, 1080, 8);
    EXPECT_EQ(bands.front().height(), 128u);
    EXPECT_EQ(bands[1].height(), 112u);   // 952 / 8 = 119 -> 112
    EXPECT_EQ(bands.size(), 28u);
    EXPECT_EQ(bands.back().height(), 8u);   // 1080 = 67 x 16 + 8
    EXPECT_TRUE(bandsOf(0, 10, 4).empty());
    EXPECT_TRUE(bandsOf(10, 0, 4).empty());
    EXPECT_THROW(bandsOf(10, 10, 0), std::invalid_argument);
}

TEST(ClusterFrames, EachFrameOnceOverTheRanks) {
    std::vector<uint32_t> frames(23);
    std::iota(frames.begin(), frames.end(), uint32_t(100));
    for (int ranks : {1, 2, 3, 8, 30}) {
        std::vector<uint32_t> all;
        for (int r = 0; r < ranks; ++r) {
            std::vector<uint32_t> share = framesOfRank(frames, r, ranks);
            EXPECT_LE(share.size(), (frames.size() + size_t(ranks) - 1) / size_t(ranks));  // balanced
            EXPECT_TRUE(std::is_sorted(share.begin(), share.end()));
            all.insert(all.end(), share.begin(), share.end());
        }
        std::sort(all.begin(), all.end());
        EXPECT_EQ(all, frames) << ranks << " ranks";
    }
    EXPECT_EQ(framesOfRank(frames, 1, 4), (std::vector<uint32_t>{101, 105, 109, 113, 117, 121}));
    EXPECT_THROW(framesOfRank(frames, 4, 4), std::invalid_argument);
    EXPECT_THROW(framesOfRank(frames, 0, 0), std::invalid_argument);
}

// What rank 0 gathers: every tile rendered into its own film (as on another rank), packed and
// unpacked into one film, is the film of one render, bit for bit, AOVs included.
TEST(ClusterTiles, TilesRenderedApartMakeTheFilmOfOneRender) {
    const Scene scene = test::wallScene(true);
    const Camera camera = test::wallCamera(72.0f / 40.0f);
    const RenderSettings settings = test::filmSettings(72, 40, 3);
    RenderCounters counters;
    Film whole(settings.width, settings.height, true);
    renderCpu(scene.view(), camera, settings, {0, settings.spp}, whole, false, counters);

    Film gathered(settings.width, settings.height, true);
    for (const PixelRect& tile : tilesOf(settings.width, settings.height, 16)) {
        Film rank(settings.width, settings.height, true);
        renderCpu(scene.view(), camera, settings, {0, settings.spp}, tile, rank, counters);
        unpackFilmRect(packFilmRect(rank, tile), tile, gathered);
    }
    test::expectSameFilmBits(whole, gathered);
    EXPECT_THROW(unpackFilmRect(std::vector<uint8_t>(5), PixelRect{0, 0, 2, 2}, gathered), std::invalid_argument);
}
