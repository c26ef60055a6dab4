#include "app/render_device.h"

#include "app/tile_renderers.h"
#include "base/input_error.h"
#include "cluster/device_list.h"
#include "cluster/tile_grid.h"
#include "cluster/tile_workers.h"

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

std::vector<int> devicesOf(const std::string& devices, const std::string& device, IntegratorKind integrator) {
    if (devices.empty()) return {};
    if (device == "cpu") throw InputError("--devices " + devices + ": not with --device cpu (the devices are GPUs)", FailureKind::Usage);
    const int count = gpuDeviceCount();
    std::vector<int> list;
    try {
        list = parseDeviceList(devices, count);   // a list that does not parse is said first
    } catch (const InputError& e) {
        if (count > 0 || e.kind() != FailureKind::Device) throw;
        // Why there is none: "urbis was built without CUDA", "no CUDA device: <the driver's error>".
        throw InputError("--devices " + devices + ": " + probeGpu().reason, FailureKind::Device);
    }
    if (list.size() > 1 && integrator != IntegratorKind::Path)
        throw InputError("--devices " + devices + ": over several GPUs only the path integrator renders (--integrator path): "
                         "the photon passes span the frame", FailureKind::Usage);
    return list;
}

RenderBackend::RenderBackend(const Scene& scene, const std::string& device, const std::vector<int>& gpus, size_t filmBytes,
                             bool verbose)
    : scene_(scene), device_(device) {
    if (device == "cpu") return;
    const bool sayDevice = verbose || device == "cuda";
    const std::vector<int> devices = gpus.empty() ? std::vector<int>{0} : gpus;
    const GpuInfo info = probeGpu(devices[0]);
    if (!info.available) {
        if (device == "cuda") throw InputError("--device cuda: " + info.reason, FailureKind::Device);
        if (sayDevice) std::fprintf(stderr, "urbis: rendering on the CPU (%s)\n", info.reason.c_str());
        return;
    }
    try {
        for (int d : devices) gpus_.push_back(GpuScene::upload(scene, filmBytes, d));
    } catch (const InputError& e) {
        if (device == "cuda") throw;
        gpus_.clear();
        std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
        return;
    }
    if (!sayDevice) return;
    std::string names;
    for (size_t i = 0; i < devices.size(); ++i)
        names += (i ? ", " : "") + gpus_[i]->info().name + (devices.size() > 1 ? " #" + std::to_string(devices[i]) : "");
    std::fprintf(stderr, "urbis: rendering on %s (cuda)\n", names.c_str());
}

RenderBackend::~RenderBackend() = default;

void RenderBackend::relight() {
    for (const std::unique_ptr<GpuScene>& gpu : gpus_) gpu->relight(scene_);
}

void RenderBackend::renderOnGpus(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                                 bool denoise, RenderCounters& counters, DeviceReport& report) {
    GpuScene& first = *gpus_[0];
    PhotonTimings photons;
    std::vector<uint32_t> tilesByDevice;
    if (gpus_.size() == 1) {
        first.setFilm(film);
        if (settings.integrator == IntegratorKind::Path) first.render(camera, settings, samples, counters);
        else first.renderPhotons(scene_, camera, settings, samples, counters, photons);
    } else {
        if (settings.integrator != IntegratorKind::Path)
            throw InputError("over several GPUs only the path integrator renders (--integrator path)", FailureKind::Usage);
        std::vector<std::unique_ptr<GpuTileRenderer>> renderers;
        std::vector<TileRenderer*> workers;
        for (const std::unique_ptr<GpuScene>& gpu : gpus_)
            for (int s = 0; s < kGpuStreamsPerDevice; ++s) {
                renderers.push_back(std::make_unique<GpuTileRenderer>(*gpu, camera, settings, samples, s == 0));
                workers.push_back(renderers.back().get());
            }
        const auto start = std::chrono::steady_clock::now();
        const TileShare share = renderTilesOnWorkers(workers, bandsOf(film.width, film.height, int(workers.size())), film);
        counters.seconds = secondsSince(start);
        counters.rays = share.rays;
        tilesByDevice.assign(gpus_.size(), 0);   // the workers are the devices' streams, device by device
        for (size_t w = 0; w < workers.size(); ++w) tilesByDevice[w / kGpuStreamsPerDevice] += share.tilesByWorker[w];
        if (denoise) first.setFilm(film);   // the gathered film, for the first GPU to denoise
    }
    const auto start = std::chrono::steady_clock::now();
    if (denoise) first.denoise();
    const double secondsDenoise = secondsSince(start);
    if (gpus_.size() == 1 || denoise) first.readFilm(film);
    const std::string name = gpus_.size() > 1 ? std::to_string(gpus_.size()) + " x " + first.info().name : first.info().name;
    report = DeviceReport{"cuda", name, first.memory(), secondsDenoise, photons, tilesByDevice};
}

void RenderBackend::render(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                           bool denoise, bool showProgress, RenderCounters& counters, DeviceReport& report) {
    if (!gpus_.empty()) {
        try {
            renderOnGpus(camera, settings, samples, film, denoise, counters, report);
            return;
        } catch (const InputError& e) {
            if (device_ == "cuda") throw;
            gpus_.clear();
            std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
        }
    }
    report = DeviceReport{"cpu", cpuModelName(), GpuMemory{}, 0.0, PhotonTimings{}, {}};
    if (settings.integrator == IntegratorKind::Path) {
        renderCpu(scene_.view(), camera, settings, samples, film, showProgress, counters);
    } else {
        PhotonState state;
        renderPhotonsCpu(scene_, camera, settings, samples, film, state, counters, report.photons);
    }
    const auto start = std::chrono::steady_clock::now();
    if (denoise) denoiseCpu(film);
    report.secondsDenoise = secondsSince(start);
}

void renderOnDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                    Film& film, bool denoise, const std::string& device, bool showProgress, bool verbose,
                    RenderCounters& counters, DeviceReport& report) {
    RenderBackend(scene, device, {}, Film::bytesFor(film.width, film.height, film.hasAovs()), verbose)
        .render(camera, settings, samples, film, denoise, showProgress, counters, report);
}

} // namespace urbis
