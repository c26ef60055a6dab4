#include "app/render_ranks.h"

#include "base/input_error.h"
#include "cluster/tile_grid.h"

#include <chrono>

namespace urbis {

std::vector<uint32_t> renderAcrossRanks(const MpiWorld& world, const Scene& scene, const Camera& camera, const RenderSettings& settings,
                       SampleRange samples, Film& film, bool denoise, const std::string& device,
                       RenderCounters& counters, DeviceReport& report) {
    if (device == "cuda")
        throw InputError("--device cuda under mpirun: the ranks render tiles on their CPUs (--device cpu; docs/scale.md)",
                         FailureKind::Usage);
    if (settings.integrator != IntegratorKind::Path)
        throw InputError("under mpirun only the path integrator renders (--integrator path): the photon passes span the frame",
                         FailureKind::Usage);
    const SceneView view = scene.view();
    const auto start = std::chrono::steady_clock::now();
    const TileShare share = renderTilesAcrossRanks(
        world, tilesOf(film.width, film.height, tileSizeFor(film.width, film.height, world.ranks())), film,
        [&](const PixelRect& tile) {
            RenderCounters tileCounters;
            renderCpu(view, camera, settings, samples, tile, film, tileCounters);
            return tileCounters.rays;
        });
    counters.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    counters.rays = share.rays;
    report = DeviceReport{"cpu", cpuModelName(), GpuMemory{}, 0.0, PhotonTimings{}};
    const auto denoiseStart = std::chrono::steady_clock::now();
    if (denoise && world.isRoot()) denoiseCpu(film);
    report.secondsDenoise = std::chrono::duration<double>(std::chrono::steady_clock::now() - denoiseStart).count();
    return share.tilesByRank;
}

} // namespace urbis
