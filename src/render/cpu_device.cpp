#include "render/cpu_device.h"

#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_photons.h"
#include "cpu/cpu_renderer.h"
#include "film/aov_display.h"
#include "geometry/scene_intersect.h"
#include "render/tile_renderers.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <fstream>
#include <stdexcept>

namespace urbis {

std::string cpuModelName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            size_t colon = line.find(':');
            if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
        }
    return "cpu";
}

CpuDevice::CpuDevice(const Scene& scene) : scene_(scene), name_(cpuModelName()) {}

SceneView CpuDevice::viewWith(const PhotonsView& photons) const {
    SceneView view = scene_.view();
    view.photons = photons;
    return view;
}

void CpuDevice::cameraPass(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                           const PhotonsView& photons, bool showProgress, RenderCounters& counters) {
    RenderCounters pass;
    renderCpu(viewWith(photons), camera, settings, samples, *film_, showProgress, pass);
    counters.rays += pass.rays;
    counters.seconds += pass.seconds;
}

std::vector<std::unique_ptr<TileRenderer>> CpuDevice::tileRenderers(const Camera& camera, const RenderSettings& settings,
                                                                    SampleRange samples, const PhotonsView& photons,
                                                                    int count) {
    return tileRenderersOf(count, [&](int) -> std::unique_ptr<TileRenderer> {
        return std::make_unique<CpuTileRenderer>(viewWith(photons), camera, settings, samples);
    });
}

void CpuDevice::denoise() { denoiseCpu(*film_); }

void CpuDevice::readFilm(Film& film) {
    if (&film != film_) film = *film_;
}

void CpuDevice::drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba) {
    if (deviceRgba) throw std::invalid_argument("CpuDevice::drawPicture: no device picture on the CPU");
    if (!denoised) {
        picture_ = displayImage(*film_, display, exposureEv);
        return;
    }
    Film copy = *film_;   // the filter leaves no unbiased sums: the film goes on from the copy
    denoiseCpu(copy);
    picture_ = displayImage(copy, display, exposureEv);
}

std::unique_ptr<PhotonPasses> CpuDevice::photonPasses(const Scene& scene) { return std::make_unique<CpuPhotonPasses>(scene); }

std::vector<float> CpuDevice::timeTrace(const std::vector<Ray>& rays, bool shadow, int, int repeats) {
    const SceneView view = scene_.view();
    std::vector<SurfaceHit> hits(rays.size());
    std::vector<uint8_t> blocked(rays.size());
    std::vector<float> ms;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t k = r.begin(); k < r.end(); ++k) {
                if (shadow) blocked[k] = occludedScene(view, rays[k]);
                else hits[k] = intersectScene(view, rays[k]);
            }
        });
        ms.push_back(float(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()));
    }
    return ms;
}

} // namespace urbis
