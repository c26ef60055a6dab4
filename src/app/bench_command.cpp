#include "app/bench_command.h"

#include "app/memory_json.h"
#include "app/memory_limit.h"
#include "io/output_paths.h"
#include "app/terrain_accuracy.h"
#include "description/scene_json.h"
#include "description/scene_parts.h"
#include "integrators/path_tracer.h"
#include "film/film_output.h"
#include "io/atomic_file.h"
#include "render/cpu_device.h"
#include "render/renderer.h"
#include "base/input_error.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace urbis {

SceneDescription benchDefaultScene() {
    SceneDescription d;
    d.film.width = 1920;
    d.film.height = 1080;
    d.integrator.spp = 1;
    d.source.buildings = 100000;
    return d;
}

BenchOptions BenchCommandLine::resolve() const {
    BenchOptions o = options;
    o.render.scene = scene.resolve();
    o.render.saveSceneFile = scene.saveScenePath();
    return o;
}

void addBenchCommand(CLI::App& app, BenchCommandLine& line) {
    CLI::App* cmd = app.add_subcommand("bench", "Rays/s of primary, diffuse and shadow rays and the time of a 1 spp "
                                                "frame, on the GPU or the CPU (kernel time, median of --repeats)");
    BenchOptions& o = line.options;
    RunOptions& r = o.render.run;
    r.device = "cuda";
    line.scene.addOptions(*cmd, {"--osm", "--buildings", "--bbox", "--width", "--height", "--spp", "--seed", "--time", "--location", "--sun",
                                 "--camera", "--camera-geo", "--geometry", "--no-streets", "--sky", "--no-aerial-perspective",
                                 "--terrain", "--dem", "--terrain-march",
                                 "--planet", "--camera-orbit", "--fov", "--clouds", "--integrator", "--photons", "--photon-radius"});
    cmd->add_option("--device", r.device, "cuda, cpu, or auto")->check(CLI::IsMember({"auto", "cpu", "cuda"}))->capture_default_str();
    cmd->add_option("--threads", r.threads, "CPU threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
    cmd->add_option("--repeats", o.repeats, "Timed runs per measurement (0: 20 on the GPU, 3 on the CPU)")->check(CLI::Range(0, 10000))->capture_default_str();
    cmd->add_option("--warmup", o.warmup, "Untimed runs first (GPU)")->check(CLI::Range(0, 1000))->capture_default_str();
    cmd->add_option("--json", o.jsonFile, "Write the results as JSON (a .json file)");
    cmd->add_flag("--terrain-accuracy", o.terrainAccuracy,
                  "Measure the terrain's marches (hierarchy, lei) against the fixed-step reference: missed intersections, "
                  "HDE, IDE and time (the terrain alone; --terrain fbm unless --dem)");
    addRunOptions(*cmd, r);
}

namespace {

using Clock = std::chrono::steady_clock;

/// The three ray batches: one primary ray per pixel (through its centre), and from each primary
/// hit (buildings or ground) one cosine-distributed bounce ray and one ray towards the sun's disk
/// (where the sun is above the surface), as the path tracer would trace them.
struct RayBatches {
    std::vector<Ray> primary, diffuse, shadow;
    size_t primaryBuildingHits = 0;
};

/// Host bytes per pixel of the batches: three rays and three flags while they are made, up to two
/// more rays in the kept diffuse and shadow batches, and a hit and a flag while they are traced.
constexpr size_t kBenchBytesPerPixel = 5 * sizeof(Ray) + 4 + sizeof(SurfaceHit);

RayBatches makeRays(const Scene& scene, const Camera& camera, const RenderSettings& settings) {
    RayBatches b;
    const uint32_t w = settings.width, h = settings.height;
    const size_t n = size_t(w) * h;
    b.primary.resize(n);
    std::vector<Ray> diffuse(n), shadow(n);
    std::vector<uint8_t> hasDiffuse(n, 0), hasShadow(n, 0), hitBuilding(n, 0);
    const SceneView view = scene.view();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i < range.end(); ++i) {
            const uint32_t x = uint32_t(i % w), y = uint32_t(i / w);
            Ray ray = camera.generateRay((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
            b.primary[i] = ray;
            SurfaceHit hit = intersectScene(view, ray);
            if (!hit.valid()) continue;
            hitBuilding[i] = hit.kind != kPrimKindOf<GroundRecord>;
            Vec3f origin = offsetRayOrigin(hit.position, hit.normal);
            SampleStream rng{settings.seed, uint32_t(i), 0, 16};
            float u1 = rng.draw(), u2 = rng.draw(), u3 = rng.draw(), u4 = rng.draw();
            diffuse[i] = Ray{origin, Frame::fromZ(hit.normal).toWorld(sampleCosineHemisphere(u1, u2))};
            hasDiffuse[i] = 1;
            Vec3f toSun = sampleSunDirection(scene.sun, u3, u4);
            if (sunEnabled(scene.sun) && dot(toSun, hit.normal) > 0.0f) {
                shadow[i] = Ray{origin, toSun};
                hasShadow[i] = 1;
            }
        }
    });
    for (size_t i = 0; i < n; ++i) {
        if (hasDiffuse[i]) b.diffuse.push_back(diffuse[i]);
        if (hasShadow[i]) b.shadow.push_back(shadow[i]);
        b.primaryBuildingHits += hitBuilding[i];
    }
    return b;
}

double median(std::vector<float> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (double(v[m - 1]) + double(v[m]));
}

struct Row {
    std::string name;
    size_t rays;
    std::vector<float> ms;
};

} // namespace

void runBench(const BenchOptions& o) {
    const RunOptions& r = o.render.run;
    const RenderSettings settings = renderSettingsOf(o.render.scene);
    size_t threads = r.threads ? r.threads : size_t(tbb::info::default_concurrency());
    tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism, threads);
    checkOutputPath("--json", o.jsonFile, {".json"});
    checkOutputPath("--save-scene", o.render.saveSceneFile, {".json"});
    checkDistinctOutputs("--json", o.jsonFile, "--save-scene", o.render.saveSceneFile);
    const size_t limit = memoryLimit(r.maxMemory);
    requireMemory(size_t(settings.width) * settings.height * kBenchBytesPerPixel + hostFilmBytes(settings.width, settings.height),
                  limit, "benchmarking " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " rays");
    if (!o.jsonFile.empty()) {
        std::FILE* probe = std::fopen((o.jsonFile + ".tmp").c_str(), "w");
        if (!probe) throw InputError(o.jsonFile + ": cannot write here", FailureKind::Output);
        std::fclose(probe);
        std::remove((o.jsonFile + ".tmp").c_str());
    }

    if (o.terrainAccuracy) {
        std::string device = r.device;
        GpuInfo gpu;
        if (device != "cpu") {
            gpu = probeGpu();
            if (!gpu.available && device == "cuda") throw InputError("--device cuda: " + gpu.reason, FailureKind::Device);
            device = gpu.available ? "cuda" : "cpu";
        }
        const bool onGpu = device == "cuda";
        runTerrainAccuracy(o, onGpu, onGpu ? gpu.name : cpuModelName(), o.repeats > 0 ? o.repeats : (onGpu ? 20 : 3));
        return;
    }

    PreparedScene prepared = prepareScene(o.render.scene, r.strict, limit);
    if (!o.render.saveSceneFile.empty()) writeSceneFile(o.render.scene, o.render.saveSceneFile);
    const Scene& scene = prepared.scene;
    RayBatches batches = makeRays(scene, prepared.camera, settings);
    const size_t extra = batches.primary.size() * (sizeof(Ray) + sizeof(SurfaceHit)) +
                         Film::bytesFor(settings.width, settings.height, false);
    const std::unique_ptr<Renderer> renderer = Renderer::make(scene, settings.integrator, {r.device, {}, extra, r.verbose, nullptr});
    const std::string device = renderer->deviceKind(), deviceName = renderer->deviceName();
    const bool onGpu = device == "cuda";
    const int repeats = o.repeats > 0 ? o.repeats : (onGpu ? 20 : 3);
    const int warmup = onGpu ? o.warmup : 0;

    std::vector<Row> rows = {{"primary", batches.primary.size(), {}},
                             {"diffuse", batches.diffuse.size(), {}},
                             {"shadow", batches.shadow.size(), {}}};
    const std::vector<Ray>* batch[3] = {&batches.primary, &batches.diffuse, &batches.shadow};
    for (int k = 0; k < 3; ++k) rows[k].ms = renderer->timeTrace(*batch[k], k == 2, warmup, repeats);
    const RenderSettings& frame = settings;
    const std::vector<float> frameMs = renderer->timeFrames(prepared.camera, frame, warmup, repeats);
    const GpuMemory memory = renderer->memory();

    std::printf("urbis bench: %s, %zu triangles, %zu BVH nodes; %s (%s)\n", prepared.summary.source.c_str(),
                scene.triangles.size(), scene.nodes.size(), deviceName.c_str(), device.c_str());
    std::printf("%-28s %10s %11s %11s %14s\n", "measurement", "rays", "median ms", "min ms", "rays/s");
    nlohmann::json json = {{"source", prepared.summary.source}, {"buildings", prepared.summary.buildings},
                           {"triangles", scene.triangles.size()}, {"walls", scene.walls.size()}, {"bvh_nodes", scene.nodes.size()},
                           {"device", device}, {"device_name", deviceName}, {"repeats", repeats},
                           {"warmup", warmup}, {"width", frame.width}, {"height", frame.height},
                           {"primary_building_hit_fraction",
                            double(batches.primaryBuildingHits) / double(std::max<size_t>(1, batches.primary.size()))}};
    for (const Row& row : rows) {
        double med = median(row.ms);
        double best = row.ms.empty() ? 0.0 : *std::min_element(row.ms.begin(), row.ms.end());
        double raysPerSecond = med > 0 ? double(row.rays) / (med * 1e-3) : 0.0;
        std::printf("%-28s %10zu %11.3f %11.3f %14.4g\n", (row.name + " rays").c_str(), row.rays, med, best,
                    raysPerSecond);
        json["rays"][row.name] = {{"count", row.rays}, {"median_ms", med}, {"min_ms", best},
                                  {"rays_per_second", raysPerSecond}, {"ms", row.ms}};
    }
    double frameMed = median(frameMs);
    double frameBest = frameMs.empty() ? 0.0 : *std::min_element(frameMs.begin(), frameMs.end());
    char label[64];
    std::snprintf(label, sizeof label, "frame %ux%u %u spp", frame.width, frame.height, frame.spp);
    std::printf("%-28s %10s %11.3f %11.3f %14s\n", label, "-", frameMed, frameBest, "-");
    json["frame"] = {{"spp", frame.spp}, {"max_depth", frame.maxDepth}, {"median_ms", frameMed}, {"min_ms", frameBest},
                     {"ms", frameMs}};
    json["bytes_device"] = memoryJson(memory);
    if (!o.jsonFile.empty()) writeTextFileAtomically(o.jsonFile, json.dump(2) + "\n");
}

} // namespace urbis
