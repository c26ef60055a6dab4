// One frame over the devices of one process without a GPU: `--devices` parsed into indices, and the
// queue of renderTilesOnWorkers driving "devices" that are the CPU renderer (a TileRenderer each, as a
// GPU is one), whose gathered film must be the film of one render, bit for bit.
#include "base/input_error.h"
#include "cluster/device_list.h"
#include "cluster/tile_grid.h"
#include "cluster/tile_queue.h"
#include "cluster/tile_workers.h"
#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <thread>

using namespace urbis;

namespace {

/// A "device" that is the CPU renderer over its tiles; `delay` makes it a slow one.
class CpuDevice final : public TileRenderer {
public:
    CpuDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings, std::chrono::milliseconds delay = {})
        : scene_(scene), camera_(camera), settings_(settings), delay_(delay) {}
    void startFrame(const Film& film) override { ++started; EXPECT_EQ(film.width, settings_.width); }
    uint64_t renderTile(const PixelRect& tile, Film& film) override {
        std::this_thread::sleep_for(delay_);
        RenderCounters counters;
        renderCpu(scene_.view(), camera_, settings_, {0, settings_.spp}, tile, film, counters);
        return counters.rays;
    }
    int started = 0;

private:
    const Scene& scene_;
    Camera camera_;
    RenderSettings settings_;
    std::chrono::milliseconds delay_;
};

/// A device whose every tile fails, as a lost GPU would.
class FailingDevice final : public TileRenderer {
public:
    void startFrame(const Film&) override {}
    uint64_t renderTile(const PixelRect&, Film&) override { throw InputError("CUDA error: device lost", FailureKind::Device); }
};

std::string deviceListError(const std::string& text, int count) {
    try {
        parseDeviceList(text, count);
    } catch (const InputError& e) {
        return std::to_string(int(e.kind())) + " " + e.what();
    }
    return "";
}

} // namespace

TEST(ClusterDevices, DeviceListsParse) {
    EXPECT_EQ(parseDeviceList("all", 4), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(parseDeviceList("all", 1), (std::vector<int>{0}));
    EXPECT_EQ(parseDeviceList("2,0", 4), (std::vector<int>{2, 0}));
    EXPECT_EQ(parseDeviceList("0,0", 1), (std::vector<int>{0, 0})) << "one GPU twice: two GpuScenes";
    EXPECT_EQ(parseDeviceList("7", 8), (std::vector<int>{7}));
}

TEST(ClusterDevices, BadDeviceListsSayWhatIsWrongInOneLine) {
    // Usage (2): the text; device (4): the machine.
    EXPECT_EQ(deviceListError("3", 2), "4 --devices 3: no CUDA device 3: this machine has 2 (0-1)");
    EXPECT_EQ(deviceListError("0,1", 1), "4 --devices 0,1: no CUDA device 1: this machine has 1 (0)");
    EXPECT_EQ(deviceListError("all", 0), "4 --devices all: this machine has no CUDA device");
    for (const char* text : {"", "x", "0,", ",0", "0,,1", "-1", "1.5", "0 1", "gpu0"}) {
        const std::string error = deviceListError(text, 8);
        EXPECT_EQ(error.rfind("2 --devices ", 0), 0u) << "'" << text << "': " << error;
        EXPECT_NE(error.find("expected all or a comma list"), std::string::npos) << error;
    }
}

TEST(ClusterDevices, QueueHandsOutEachIndexOnceAcrossThreads) {
    TileQueue queue(1000);
    std::vector<std::atomic<int>> taken(1000);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int32_t i; (i = queue.take()) >= 0;) ++taken[size_t(i)];
        });
    for (std::thread& t : threads) t.join();
    for (const std::atomic<int>& n : taken) ASSERT_EQ(n.load(), 1);
    EXPECT_EQ(queue.take(), -1);
}

TEST(ClusterDevices, TilesOverCpuDevicesMakeTheFilmOfOneRender) {
    // The wall of the MPI tiles' test (cluster_tiles_test.cpp), 72 x 40 at 3 spp, on three devices, one
    // of them slow: the queue gives it fewer tiles, and the film is the one of one render.
    const Scene scene = test::wallScene(true);
    const Camera camera = test::wallCamera(72.0f / 40.0f);
    const RenderSettings settings = test::filmSettings(72, 40, 3);
    CpuDevice fast(scene, camera, settings), slow(scene, camera, settings, std::chrono::milliseconds(20)),
        other(scene, camera, settings);
    const std::vector<PixelRect> tiles = tilesOf(settings.width, settings.height, 16);   // 15 tiles
    Film gathered(settings.width, settings.height, true);
    const TileShare share = renderTilesOnWorkers({&fast, &slow, &other}, tiles, gathered);
    Film whole(settings.width, settings.height, true);
    RenderCounters counters;
    renderCpu(scene.view(), camera, settings, {0, settings.spp}, whole, false, counters);
    test::expectSameFilmBits(whole, gathered);
    EXPECT_EQ(share.rays, counters.rays);
    ASSERT_EQ(share.tilesByWorker.size(), 3u);
    EXPECT_EQ(std::accumulate(share.tilesByWorker.begin(), share.tilesByWorker.end(), 0u), tiles.size());
    EXPECT_LT(share.tilesByWorker[1], share.tilesByWorker[0] + share.tilesByWorker[2]) << "the slow device took as many";
    EXPECT_EQ(fast.started + slow.started + other.started, 3) << "each device starts the frame once, not per tile";
}

TEST(ClusterDevices, ADeviceThatFailsFailsTheFrame) {
    const Scene scene = test::wallScene(true);
    const RenderSettings settings = test::filmSettings(48, 32, 1);
    // The good device sleeps 50 ms a tile, so that the failing one's thread takes a tile of the 24
    // before they are gone, however late the scheduler starts it.
    CpuDevice good(scene, test::wallCamera(1.5f), settings, std::chrono::milliseconds(50));
    FailingDevice bad;
    Film film(settings.width, settings.height, false);
    try {
        renderTilesOnWorkers({&good, &bad}, tilesOf(settings.width, settings.height, 8), film);
        FAIL() << "the failing device's error was lost";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "CUDA error: device lost");
    }
}
