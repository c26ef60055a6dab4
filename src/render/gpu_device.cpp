#include "render/gpu_device.h"

#include "render/tile_renderers.h"

namespace urbis {

GpuDevice::GpuDevice(const Scene& scene, size_t extraBytes, int device) : gpu_(GpuScene::upload(scene, extraBytes, device)) {}

void GpuDevice::cameraPass(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                           const PhotonsView& photons, bool, RenderCounters& counters) {
    RenderCounters pass;
    gpu_->render(camera, settings, samples, pass, photons);
    counters.rays += pass.rays;
    counters.seconds += pass.seconds;
}

std::vector<std::unique_ptr<TileRenderer>> GpuDevice::tileRenderers(const Camera& camera, const RenderSettings& settings,
                                                                    SampleRange samples, const PhotonsView& photons,
                                                                    int count) {
    return tileRenderersOf(count, [&](int i) -> std::unique_ptr<TileRenderer> {
        return std::make_unique<GpuTileRenderer>(*gpu_, camera, settings, samples, photons, i == 0);
    });
}

} // namespace urbis
