#include "app/render_ranks.h"

#include "app/tile_renderers.h"
#include "base/input_error.h"
#include "cluster/tile_grid.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace urbis {

namespace {
double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

int gpuOfRank(const MpiWorld& world) {
    const int count = gpuDeviceCount();
    if (count == 0) throw InputError("--device cuda under mpirun: " + probeGpu().reason, FailureKind::Device);
    return world.localRank() % count;
}

std::vector<uint32_t> renderAcrossRanks(const MpiWorld& world, const Scene& scene, const Camera& camera, const RenderSettings& settings,
                       SampleRange samples, Film& film, bool denoise, const std::string& device,
                       RenderCounters& counters, DeviceReport& report) {
    if (settings.integrator != IntegratorKind::Path)
        throw InputError("under mpirun only the path integrator renders (--integrator path): the photon passes span the frame",
                         FailureKind::Usage);
    const bool onGpu = device == "cuda";
    std::unique_ptr<GpuScene> gpu;
    std::unique_ptr<TileRenderer> renderer;
    if (onGpu) {
        gpu = GpuScene::upload(scene, Film::bytesFor(film.width, film.height, film.hasAovs()), gpuOfRank(world));
        renderer = std::make_unique<GpuTileRenderer>(*gpu, camera, settings, samples);
        report = DeviceReport{"cuda", gpu->info().name, GpuMemory{}, 0.0, PhotonTimings{}, {}};
    } else {
        renderer = std::make_unique<CpuTileRenderer>(scene.view(), camera, settings, samples);
        report = DeviceReport{"cpu", cpuModelName(), GpuMemory{}, 0.0, PhotonTimings{}, {}};
    }
    const uint32_t side = tileSizeFor(film.width, film.height, world.ranks(), onGpu ? kGpuTileSide : 64);
    const auto start = std::chrono::steady_clock::now();
    const TileShare share = renderTilesAcrossRanks(world, tilesOf(film.width, film.height, side), film, *renderer);
    counters.seconds = secondsSince(start);
    counters.rays = share.rays;
    const auto denoiseStart = std::chrono::steady_clock::now();
    if (denoise && world.isRoot()) {
        if (gpu) {   // as one process on the GPU denoises: on the device, from the gathered film
            gpu->setFilm(film);
            gpu->denoise();
            gpu->readFilm(film);
        } else {
            denoiseCpu(film);
        }
    }
    report.secondsDenoise = secondsSince(denoiseStart);
    if (gpu) report.memory = gpu->memory();
    return share.tilesByWorker;
}

} // namespace urbis
