#include "render/renderer.h"

#include "base/step_timer.h"
#include "base/input_error.h"
#include "cluster/tile_grid.h"
#include "cluster/tile_workers.h"
#include "render/cpu_device.h"
#include "render/gpu_device.h"

#include <cstdio>

namespace urbis {

namespace {

/// Seconds of a light pass's parts so far (the GPU's: event times).
double lightPassSeconds(const PhotonTimings& t) { return t.flags + t.photons + t.grid; }

bool acrossRanks(const RendererOptions& options) { return options.world && options.world->ranks() > 1; }

/// The GPUs `options` asks for, uploaded to; empty where the CPU renders ("auto" without a usable GPU).
std::vector<std::unique_ptr<RenderDevice>> gpusOf(const Scene& scene, const RendererOptions& options) {
    std::vector<std::unique_ptr<RenderDevice>> gpus;
    if (options.device == "cpu") return gpus;
    if (acrossRanks(options)) {   // each rank on the GPU of its local rank, only where asked for
        if (options.device == "cuda") gpus.push_back(std::make_unique<GpuDevice>(scene, options.filmBytes, gpuOfRank(*options.world)));
        return gpus;
    }
    const bool sayDevice = options.verbose || options.device == "cuda";
    const std::vector<int> devices = options.gpus.empty() ? std::vector<int>{0} : options.gpus;
    const GpuInfo info = probeGpu(devices[0]);
    if (!info.available) {
        if (options.device == "cuda") throw InputError("--device cuda: " + info.reason, FailureKind::Device);
        if (sayDevice) std::fprintf(stderr, "urbis: rendering on the CPU (%s)\n", info.reason.c_str());
        return gpus;
    }
    try {
        for (int d : devices) gpus.push_back(std::make_unique<GpuDevice>(scene, options.filmBytes, d));
    } catch (const InputError& e) {
        if (options.device == "cuda") throw;
        std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
        return {};
    }
    if (!sayDevice) return gpus;
    std::string names;
    for (size_t i = 0; i < devices.size(); ++i)
        names += (i ? ", " : "") + gpus[i]->name() + (devices.size() > 1 ? " #" + std::to_string(devices[i]) : "");
    std::fprintf(stderr, "urbis: rendering on %s (cuda)\n", names.c_str());
    return gpus;
}

} // namespace

int gpuOfRank(const MpiWorld& world) {
    const int count = gpuDeviceCount();
    if (count == 0) throw InputError("--device cuda under mpirun: " + probeGpu().reason, FailureKind::Device);
    return world.localRank() % count;
}

Renderer::Renderer(const Scene& scene, const RendererOptions& options)
    : scene_(scene), options_(options), devices_(gpusOf(scene, options)) {
    if (devices_.empty()) devices_.push_back(std::make_unique<CpuDevice>(scene));
}

Renderer::~Renderer() = default;

std::vector<SampleRange> Renderer::roundsOf(SampleRange samples) const {
    if (!hasLightPass()) return {samples};
    std::vector<SampleRange> rounds;
    for (uint32_t s = samples.first; s < samples.first + samples.count; ++s) rounds.push_back({s, 1});
    return rounds;
}

PhotonsView Renderer::passesOnFirst(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                                    bool showProgress, RenderCounters& counters, PhotonTimings& timings) {
    const std::vector<SampleRange> rounds = roundsOf(samples);
    PhotonsView photons;
    for (const SampleRange& round : rounds) {
        if (hasLightPass()) photons = countedLightPass(0, camera, settings, round.first, counters, timings);
        const double before = counters.seconds;
        devices_[0]->cameraPass(camera, settings, round, photons, showProgress && rounds.size() == 1, counters);
        timings.camera += counters.seconds - before;
    }
    return photons;
}

PhotonsView Renderer::countedLightPass(size_t device, const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                       RenderCounters& counters, PhotonTimings& timings) {
    const double seconds = lightPassSeconds(timings);
    const uint64_t rays = timings.photonRays;
    const PhotonsView photons = lightPass(device, camera, settings, sample, timings);
    counters.seconds += lightPassSeconds(timings) - seconds;
    counters.rays += timings.photonRays - rays;
    return photons;
}

void Renderer::renderOnOne(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                           bool denoise, bool showProgress, RenderCounters& counters, DeviceReport& report) {
    RenderDevice& device = *devices_[0];
    device.setFilm(film);
    PhotonTimings timings;
    const PhotonsView last = passesOnFirst(camera, settings, samples, showProgress, counters, timings);
    if (samples.count > 0) report.photons = reportPasses(camera, settings, samples.first + samples.count - 1, last, timings);
    report.secondsDenoise = denoiseOnFirst(film, denoise, false);
    if (!denoise) device.readFilm(film);
}

void Renderer::renderOnDevices(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                               bool denoise, RenderCounters& counters, DeviceReport& report) {
    const auto start = SteadyClock::now();
    std::vector<PhotonTimings> timings(devices_.size());
    std::vector<RenderCounters> lightCounters(devices_.size());
    std::vector<PhotonsView> photons(devices_.size());
    std::vector<uint32_t> tilesByDevice(devices_.size(), 0);
    for (const SampleRange& round : roundsOf(samples)) {
        // Each device runs the round's light pass itself (the same photons on each), then all take
        // bands of the camera pass from one queue; a round's first stream of each device makes its
        // device film from the host film, which holds every band of the rounds before.
        if (hasLightPass())
            runOnWorkerThreads(devices_.size(), [&](size_t d) {
                photons[d] = countedLightPass(d, camera, settings, round.first, lightCounters[d], timings[d]);
            });
        std::vector<std::unique_ptr<TileRenderer>> renderers;
        std::vector<TileRenderer*> workers;
        std::vector<size_t> deviceOf;
        for (size_t d = 0; d < devices_.size(); ++d)
            for (std::unique_ptr<TileRenderer>& r :
                 devices_[d]->tileRenderers(camera, settings, round, photons[d], devices_[d]->tileStreams())) {
                workers.push_back(r.get());
                deviceOf.push_back(d);
                renderers.push_back(std::move(r));
            }
        const TileShare share = renderTilesOnWorkers(workers, bandsOf(film.width, film.height, int(workers.size())), film);
        counters.rays += share.rays;
        for (size_t w = 0; w < workers.size(); ++w) tilesByDevice[deviceOf[w]] += share.tilesByWorker[w];
    }
    for (const RenderCounters& c : lightCounters) counters.rays += c.rays;
    counters.seconds = secondsSince(start);
    if (samples.count > 0) report.photons = reportPasses(camera, settings, samples.first + samples.count - 1, photons[0], timings[0]);
    report.tilesByDevice = tilesByDevice;
    report.secondsDenoise = denoiseOnFirst(film, denoise, true);
}

void Renderer::renderAcrossRanks(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film,
                                 bool denoise, RenderCounters& counters, DeviceReport& report) {
    const MpiWorld& world = *options_.world;
    RenderDevice& device = *devices_[0];
    const bool onGpu = std::string(device.kind()) == "cuda";
    const std::vector<PixelRect> tiles =
        tilesOf(film.width, film.height, tileSizeFor(film.width, film.height, world.ranks(), onGpu ? kGpuTileSide : 64));
    const auto start = SteadyClock::now();
    PhotonTimings timings;
    PhotonsView photons;
    bool first = true;
    for (const SampleRange& round : roundsOf(samples)) {
        // A tile goes on from the samples any rank added to it in the rounds before: rank 0's film.
        if (!first) world.broadcastFilm(film);
        first = false;
        if (hasLightPass()) photons = countedLightPass(0, camera, settings, round.first, counters, timings);
        std::unique_ptr<TileRenderer> renderer = std::move(device.tileRenderers(camera, settings, round, photons, 1)[0]);
        const TileShare share = renderTilesAcrossRanks(world, tiles, film, *renderer);
        counters.rays += share.rays;
        if (report.tilesByRank.empty()) report.tilesByRank = share.tilesByWorker;
        else
            for (size_t r = 0; r < share.tilesByWorker.size(); ++r) report.tilesByRank[r] += share.tilesByWorker[r];
    }
    counters.seconds = secondsSince(start);
    if (samples.count > 0) report.photons = reportPasses(camera, settings, samples.first + samples.count - 1, photons, timings);
    // As one process denoises: on rank 0's device, from the gathered film.
    if (world.isRoot()) report.secondsDenoise = denoiseOnFirst(film, denoise, true);
}

double Renderer::denoiseOnFirst(Film& film, bool denoise, bool upload) {
    if (!denoise) return 0;
    const auto start = SteadyClock::now();
    RenderDevice& device = *devices_[0];
    if (upload) device.setFilm(film);
    device.denoise();
    device.readFilm(film);
    return secondsSince(start);
}

void Renderer::render(const Camera& camera, const RenderSettings& settings, SampleRange samples, Film& film, bool denoise,
                      bool showProgress, RenderCounters& counters, DeviceReport& report) {
    counters = {};
    report = DeviceReport{};
    try {
        if (acrossRanks(options_)) renderAcrossRanks(camera, settings, samples, film, denoise, counters, report);
        else if (devices_.size() > 1) renderOnDevices(camera, settings, samples, film, denoise, counters, report);
        else renderOnOne(camera, settings, samples, film, denoise, showProgress, counters, report);
    } catch (const InputError& e) {
        if (options_.device != "auto" || std::string(deviceKind()) == "cpu") throw;
        std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
        devices_.clear();
        devices_.push_back(std::make_unique<CpuDevice>(scene_));
        forgetState();
        counters = {};
        report = DeviceReport{};
        renderOnOne(camera, settings, samples, film, denoise, showProgress, counters, report);
    }
    report.device = deviceKind();
    report.name = devices_.size() > 1 ? std::to_string(devices_.size()) + " x " + deviceName() : deviceName();
    report.memory = memory();
}

void Renderer::startFilm(Film& film) { devices_[0]->setFilm(film); }

void Renderer::addSamples(const Camera& camera, const RenderSettings& settings, SampleRange samples, RenderCounters& counters) {
    counters = {};
    PhotonTimings timings;
    passesOnFirst(camera, settings, samples, false, counters, timings);
}

void Renderer::readFilm(Film& film) { devices_[0]->readFilm(film); }

void Renderer::drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba) {
    devices_[0]->drawPicture(display, exposureEv, denoised, deviceRgba);
}

Rgb8Image Renderer::picture() const { return devices_[0]->picture(); }

std::vector<float> Renderer::timeFrames(const Camera& camera, const RenderSettings& settings, int warmup, int repeats) {
    Film film(settings.width, settings.height, false);
    devices_[0]->setFilm(film);
    const SampleRange samples{0, settings.spp};
    std::vector<float> ms;
    for (int i = 0; i < warmup + repeats; ++i) {
        RenderCounters counters;
        PhotonTimings timings;
        passesOnFirst(camera, settings, samples, false, counters, timings);
        if (i >= warmup) ms.push_back(float(counters.seconds * 1e3));
    }
    return ms;
}

std::vector<float> Renderer::timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats) {
    return devices_[0]->timeTrace(rays, shadow, warmup, repeats);
}

void Renderer::relight() {
    for (std::unique_ptr<RenderDevice>& device : devices_) device->relight(scene_);
    forgetState();
}

GpuMemory Renderer::memory() const {
    GpuMemory memory = devices_[0]->memory();
    if (std::string(deviceKind()) == "cuda") memory.rays += stateBytes();
    return memory;
}

} // namespace urbis
