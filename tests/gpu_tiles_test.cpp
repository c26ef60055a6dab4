// The GPU renders a frame in tiles (MPI ranks, several devices) and keeps one upload for a sequence:
// tiles on several streams give the whole frame's pixels bit for bit, a relit scene renders as a fresh
// upload of it, and `--devices 0,0` (two GpuScenes on one GPU, their streams at once) writes the image
// of `--device cuda`.
#include "gpu_test_support.h"
#include "cli_support.h"
#include "film_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "citygen/window_schedule.h"
#include "cluster/tile_grid.h"
#include "cluster/tile_queue.h"
#include "cluster/tile_workers.h"
#include "prepare/scene_lighting.h"
#include "lights/light_build.h"
#include "media/atmosphere_build.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

using namespace urbis;
using namespace urbis::test;

namespace {

/// The Bavarian village with procedural walls under the atmosphere, its sun at `sunElevation` degrees
/// and its windows lit for `hour`, with the light list built; `camera` frames it.
Scene litVillage(float sunElevation, float hour, const RenderSettings& settings, Camera& camera) {
    CityModel city = importOsm(villageFile(), ImportOptions{});
    CityMeshOptions options;
    options.geometry = parseGeometryModes("procedural");
    CityMesh mesh = meshCity(city, options);
    Scene scene = buildCityScene(mesh);
    camera = frameCity(mesh.cityBounds, 50.0f, float(settings.width) / float(settings.height));
    scene.sky.model = SkyModel::Atmosphere;
    scene.sun = makeSun(sunElevation, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    relightWindows(scene, std::vector<WindowUse>(city.buildings.size() + 1, WindowUse::Residential), hour);
    buildAtmosphere(scene);
    buildLights(scene);
    return scene;
}

/// filmSettings with the seed the tests below render at.
RenderSettings smallSettings(uint32_t width, uint32_t height, uint32_t spp) {
    RenderSettings settings = filmSettings(width, height, spp);
    settings.seed = 5;
    return settings;
}

/// The film of `samples` rendered on `gpu` in one launch.
Film wholeFrame(GpuScene& gpu, const Camera& camera, const RenderSettings& settings, bool aovs) {
    Film film(settings.width, settings.height, aovs);
    RenderCounters counters;
    gpu.setFilm(film);
    gpu.render(camera, settings, {0, settings.spp}, counters);
    gpu.readFilm(film);
    return film;
}

} // namespace

TEST(GpuTiles, TilesGiveTheWholeFramesPixelsBitForBit) {
    URBIS_SKIP_WITHOUT_GPU();
    const RenderSettings settings = smallSettings(150, 97, 8);   // tiles of 32 and ragged edges
    Camera camera;
    const Scene scene = litVillage(30.0f, 14.0f, settings, camera);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const Film whole = wholeFrame(*gpu, camera, settings, true);

    // Three streams of the one device, a host thread each, taking tiles from one queue in reverse
    // order (any order and any stream: the bits are the pixel's).
    Film tiled(settings.width, settings.height, true);
    gpu->setFilm(tiled);
    std::vector<GpuTileStream> streams;
    for (int s = 0; s < 3; ++s) streams.emplace_back(*gpu);
    const std::vector<PixelRect> tiles = tilesOf(settings.width, settings.height, 32);
    TileQueue queue(tiles.size());
    std::atomic<uint64_t> rays{0};
    std::vector<size_t> tilesByStream(streams.size(), 0);
    const auto start = std::chrono::steady_clock::now();
    runOnWorkerThreads(streams.size(), [&](size_t s) {
        for (int32_t i; (i = queue.take()) >= 0; ++tilesByStream[s])
            rays += streams[s].renderTile(camera, settings, {0, settings.spp}, tiles[tiles.size() - 1 - size_t(i)], tiled);
    });
    std::printf("%zu tiles of 32 px on 3 streams (%zu, %zu, %zu): %.2f ms, %llu rays\n", tiles.size(), tilesByStream[0],
                tilesByStream[1], tilesByStream[2],
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
                (unsigned long long)rays);
    expectSameFilmBits(whole, tiled);
    EXPECT_GT(rays, size_t(settings.width) * settings.height * settings.spp);
    EXPECT_THROW(streams[0].renderTile(camera, settings, {0, 1}, PixelRect{0, 0, 151, 10}, tiled), std::invalid_argument);
    Film otherSize(settings.width, settings.height + 1, true);
    EXPECT_THROW(streams[0].renderTile(camera, settings, {0, 1}, PixelRect{0, 0, 8, 8}, otherSize), std::invalid_argument);
}

TEST(GpuTiles, RelitSceneRendersAsAFreshUploadOfIt) {
    URBIS_SKIP_WITHOUT_GPU();
    const RenderSettings settings = smallSettings(96, 64, 4);
    Camera camera;
    Scene scene = litVillage(30.0f, 14.0f, settings, camera);
    std::unique_ptr<GpuScene> kept = GpuScene::upload(scene);
    const Film day = wholeFrame(*kept, camera, settings, false);

    // Dusk: the sun low, the rooms of the evening lit, the sky's tables and the light list rebuilt.
    const Scene dusk = litVillage(2.0f, 20.5f, settings, camera);
    scene = dusk;
    auto t0 = std::chrono::steady_clock::now();
    kept->relight(scene);
    const double relightMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    t0 = std::chrono::steady_clock::now();
    std::unique_ptr<GpuScene> fresh = GpuScene::upload(dusk);
    const double uploadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("village: relight %.2f ms, fresh upload %.2f ms\n", relightMs, uploadMs);
    const Film relit = wholeFrame(*kept, camera, settings, false);
    expectSameFilmBits(wholeFrame(*fresh, camera, settings, false), relit);
    EXPECT_NE(std::memcmp(day.arrays.radianceSum.data(), relit.arrays.radianceSum.data(),
                          relit.arrays.radianceSum.size() * sizeof(Vec3f)), 0) << "the relit scene renders as the day";
}

namespace {
const std::string kSmall = "render --width 150 --height 90 --spp 4 --buildings 60 ";
} // namespace

TEST(GpuTiles, TwoDevicesOnOneGpuWriteTheImageOfOne) {
    URBIS_SKIP_WITHOUT_GPU();
    auto dir = scratchDir("gpu_devices");
    CommandResult one = runUrbis(kSmall + "--device cuda --denoise --out one.png", dir);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    CommandResult two = runUrbis(kSmall + "--devices 0,0 --denoise --verbose --out two.png --stats two.json", dir);
    ASSERT_EQ(two.exitCode, 0) << two.err;
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png")) << "the tiles of two devices are not the frame of one";
    EXPECT_NE(two.err.find("#0, "), std::string::npos) << "names both devices:\n" << two.err;
    const auto stats = nlohmann::json::parse(readFile(dir / "two.json"));
    EXPECT_EQ(stats.at("device_name").get<std::string>().rfind("2 x ", 0), 0u) << "device_name counts the GPUs";
    const std::vector<uint32_t> bands = stats.at("tiles_by_device").get<std::vector<uint32_t>>();
    ASSERT_EQ(bands.size(), 2u);
    EXPECT_EQ(bands[0] + bands[1], bandsOf(150, 90, 2 * kGpuStreamsPerDevice).size()) << "a band lost or rendered twice";
    CommandResult single = runUrbis(kSmall + "--devices 0 --denoise --out single.png", dir);
    ASSERT_EQ(single.exitCode, 0) << single.err;
    EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "single.png")) << "--devices 0 is not --device cuda";
}

// The photon integrators over two devices: each device's light pass of a sample, then the bands of its
// camera pass from one queue, a round a sample; the frame of one device, bit for bit.
TEST(GpuTiles, PhotonIntegratorsOverTwoDevicesWriteTheImageOfOne) {
    URBIS_SKIP_WITHOUT_GPU();
    auto dir = scratchDir("gpu_devices_photons");
    for (const std::string integrator : {"photon-map", "photon-buffers"}) {
        const std::string frame = kSmall + "--integrator " + integrator + " --photons 20000 ";
        CommandResult one = runUrbis(frame + "--device cuda --out one.png", dir);
        ASSERT_EQ(one.exitCode, 0) << one.err;
        CommandResult two = runUrbis(frame + "--devices 0,0 --out two.png --stats two.json", dir);
        ASSERT_EQ(two.exitCode, 0) << two.err;
        EXPECT_EQ(readFile(dir / "one.png"), readFile(dir / "two.png")) << integrator;
        const auto stats = nlohmann::json::parse(readFile(dir / "two.json"));
        EXPECT_GT(stats.at("photons").at("photon_rays").get<uint64_t>(), 0u) << integrator;
    }
}

TEST(GpuTiles, SequenceOverTwoDevicesWritesTheFramesOfOne) {
    URBIS_SKIP_WITHOUT_GPU();
    auto dir = scratchDir("gpu_devices_frames");
    // Four frames from afternoon to night: each frame relights the kept upload.
    std::ofstream(dir / "anim.json") << R"({"source": {"buildings": 40, "seed": 3}, "integrator": {"spp": 2},
        "film": {"width": 64, "height": 40}, "animation": {"fps": 1,
        "camera": [{"time": 0, "position": [200, 100, 60], "target": [0, 10, 0]},
                   {"time": 3, "position": [-150, 80, 120], "target": [0, 10, 0]}],
        "time": [{"time": 0, "date": "2024-06-21T16:00+00:00"}, {"time": 3, "date": "2024-06-21T22:30+00:00"}]}})";
    CommandResult one = runUrbis("render --scene anim.json --frames 0:3 --device cuda --out one/f%d.png", dir);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    CommandResult two = runUrbis("render --scene anim.json --frames 0:3 --devices 0,0 --out two/f%d.png", dir);
    ASSERT_EQ(two.exitCode, 0) << two.err;
    for (int n = 0; n < 4; ++n) {
        const std::string name = "f" + std::to_string(n) + ".png";
        EXPECT_EQ(readFile(dir / "one" / name), readFile(dir / "two" / name)) << name;
    }
    // Frame 3 alone (a fresh upload, relit once) is frame 3 of the sequence (relit three times).
    ASSERT_EQ(runUrbis("render --scene anim.json --frames 3 --device cuda --out alone/f%d.png", dir).exitCode, 0);
    EXPECT_EQ(readFile(dir / "one" / "f3.png"), readFile(dir / "alone" / "f3.png"));
}

TEST(GpuTiles, BadDevicesSayWhyInOneLine) {
    auto dir = scratchDir("gpu_devices_bad");
    CommandResult missing = runUrbis(kSmall + "--devices 0,63", dir);
    EXPECT_EQ(missing.exitCode, 4) << missing.err;
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    EXPECT_NE(missing.err.find("--devices 0,63: "), std::string::npos) << missing.err;
    CommandResult cpu = runUrbis(kSmall + "--devices 0 --device cpu", dir);
    EXPECT_EQ(cpu.exitCode, 2) << cpu.err;
    EXPECT_NE(cpu.err.find("not with --device cpu"), std::string::npos) << cpu.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "urbis.png"));
}
