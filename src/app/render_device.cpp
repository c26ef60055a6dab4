#include "app/render_device.h"

#include "base/input_error.h"

#include <chrono>
#include <cstdio>
#include <fstream>

namespace urbis {

namespace {
double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

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

void renderOnDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                    Film& film, bool denoise, const std::string& device, bool showProgress, bool verbose,
                    RenderCounters& counters, DeviceReport& report) {
    const bool sayDevice = verbose || device == "cuda";
    if (device != "cpu") {
        GpuInfo info = probeGpu();
        if (!info.available && device == "cuda") throw InputError("--device cuda: " + info.reason, FailureKind::Device);
        if (info.available) {
            try {
                std::unique_ptr<GpuScene> gpu =
                    GpuScene::upload(scene, Film::bytesFor(film.width, film.height, film.hasAovs()));
                if (sayDevice) std::fprintf(stderr, "urbis: rendering on %s (cuda)\n", info.name.c_str());
                gpu->setFilm(film);
                PhotonTimings photons;
                if (settings.integrator == IntegratorKind::Path) gpu->render(camera, settings, samples, counters);
                else gpu->renderPhotons(scene, camera, settings, samples, counters, photons);
                const auto start = std::chrono::steady_clock::now();
                if (denoise) gpu->denoise();
                const double secondsDenoise = secondsSince(start);
                gpu->readFilm(film);
                report = DeviceReport{"cuda", info.name, gpu->memory(), secondsDenoise, photons};
                return;
            } catch (const InputError& e) {
                if (device == "cuda") throw;
                std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
            }
        } else if (sayDevice) {
            std::fprintf(stderr, "urbis: rendering on the CPU (%s)\n", info.reason.c_str());
        }
    }
    report = DeviceReport{"cpu", cpuModelName(), GpuMemory{}, 0.0, PhotonTimings{}};
    if (settings.integrator == IntegratorKind::Path) {
        renderCpu(scene.view(), camera, settings, samples, film, showProgress, counters);
    } else {
        PhotonState state;
        renderPhotonsCpu(scene, camera, settings, samples, film, state, counters, report.photons);
    }
    const auto start = std::chrono::steady_clock::now();
    if (denoise) denoiseCpu(film);
    report.secondsDenoise = secondsSince(start);
}

} // namespace urbis
