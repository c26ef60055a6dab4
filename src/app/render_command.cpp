#include "app/render_command.h"

#include "base/step_timer.h"
#include "app/devices_option.h"
#include "app/memory_json.h"
#include "app/memory_limit.h"
#include "app/render_frames.h"
#include "base/host_memory.h"
#include "base/input_error.h"
#include "description/scene_checks.h"
#include "description/scene_json.h"
#include "description/scene_parts.h"
#include "film/film_output.h"
#include "io/atomic_file.h"
#include "io/output_paths.h"
#include "render/renderer.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstdio>
#include <unistd.h>

namespace urbis {

void addRenderCommand(CLI::App& app, RenderCommandLine& line) {
    CLI::App* cmd = app.add_subcommand("render", "Path trace a city to a PNG (the generated default world without --osm)");
    line.scene.addOptions(*cmd);
    RunOptions& o = line.run;
    cmd->add_option("--threads", o.threads, "CPU threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
    cmd->add_option("--stats", o.statsFile, "Write counts, memory, timings and rays/s as JSON (a .json file)");
    cmd->add_option("--device", o.device, "auto (the GPU if usable, else the CPU), cpu or cuda")
        ->check(CLI::IsMember({"auto", "cpu", "cuda"}))->capture_default_str();
    cmd->add_option("--devices", o.devices,
                    "all or 0,1,...: the CUDA devices to spread tiles (and --frames) over, one process (docs/multi_gpu.md)");
    addRunOptions(*cmd, o);
    FrameOptions& f = line.frames;
    cmd->add_option("--frames", f.frames,
                    "A:B, A or A: frames of the scene's animation to render (from 0; --out then holds %04d: frames/f%04d.png)");
    cmd->add_flag("--overwrite", f.overwrite, "With --frames: render the frames whose files exist too (default: keep them)");
    cmd->add_option("--video", f.video, "With --frames: encode them with ffmpeg into this .mp4 or .gif");
}

void addRunOptions(CLI::App& cmd, RunOptions& o) {
    cmd.add_option("--max-memory", o.maxMemory,
                   "Host memory the run may take, e.g. 8G, 512M, 2000000000 (default: 80 % of the memory available)");
    cmd.add_flag("--strict", o.strict, "Treat warnings (a camera inside a building, underground or far away) as errors");
    cmd.add_flag("--verbose", o.verbose, "Say which device renders and why");
}

namespace {

/// The scene's bytes by array, with the stored triangles of each street kind (roads, junctions,
/// sidewalks, ground cover, water, bridges, railways, the lamps' twin) under that kind's key rather than
/// under `triangles` and `triangle_info`: the keys still add up to the scene's total.
nlohmann::json bytesByKind(const SceneMemory& memory, const std::map<std::string, size_t>& trianglesByKind) {
    nlohmann::json json = memoryJson(memory);
    constexpr size_t kTriangleBytes = sizeof(Triangle) + sizeof(TriangleInfo);
    for (const auto& [kind, n] : trianglesByKind) {
        if (kind == "walls" || kind == "roofs") continue;
        json["triangles"] = json["triangles"].get<size_t>() - n * sizeof(Triangle);
        json["triangle_info"] = json["triangle_info"].get<size_t>() - n * sizeof(TriangleInfo);
        json[kind] = json.value(kind, size_t(0)) + n * kTriangleBytes;
    }
    return json;
}

/// Writes --stats: counts, what was dropped and repaired, memory (the scene's, the peak host and
/// device bytes), timings, rays/s and the scene description.
void writeStats(const RenderOptions& o, const PreparedScene& prepared, const RenderSettings& settings,
                const RenderCounters& counters, const DeviceReport& device, size_t threads, double secondsWrite) {
    const BuildSummary& summary = prepared.summary;
    const Scene& scene = prepared.scene;
    SceneMemory memory = scene.memory();
    nlohmann::json stats = {
        {"source", summary.source},
        {"counts", summary.counts},
        {"dropped", summary.dropped},
        {"repaired", summary.repaired},
        {"triangles", scene.triangles.size()},
        {"triangles_by_kind", summary.trianglesByKind},
        {"geometry", {{"walls", representationName(prepared.geometry.walls)},
                      // Of the roofs only the parapets are procedural; plain roofs are stored triangles.
                      {"roofs", representationName(prepared.geometry.roofs == Representation::Procedural
                                                       ? Representation::Procedural
                                                       : Representation::Triangles)}}},
        {"walls", scene.walls.empty() ? size_t(0) : summary.facadeWalls},
        {"wall_tiles", scene.walls.size()},
        {"wall_tile_size", o.scene.geometry.wallTiles},
        {"facade_walls", summary.facadeWalls},
        {"facade_cells", summary.facadeCells},
        {"bvh_nodes", scene.nodes.size()},
        {"materials", scene.materials.size()},
        {"bytes_scene", memory.total()},
        {"bytes_by_kind", bytesByKind(memory, summary.trianglesByKind)},
        {"width", settings.width}, {"height", settings.height}, {"spp", settings.spp},
        {"seed", settings.seed}, {"threads", threads}, {"device", device.device},
        {"device_name", device.name},
        {"bytes_device", memoryJson(device.memory)},
        // The high-water mark of the whole run (VmHWM), what is resident once rendered (the city and
        // its mesh released), and the GpuScene's total where the GPU rendered.
        {"peak_host_bytes", peakHostBytes()},
        {"resident_host_bytes", residentHostBytes()},
        {"peak_device_bytes", device.device == "cuda" ? nlohmann::json(device.memory.total()) : nlohmann::json(nullptr)},
        {"seconds", {{"import", prepared.secondsImport}, {"citygen", prepared.secondsCitygen}, {"bvh", prepared.secondsBvh},
                     {"render", counters.seconds}, {"denoise", device.secondsDenoise}, {"write", secondsWrite}}},
        {"seconds_render", counters.seconds},
        {"rays", counters.rays},
        {"tiles_by_rank", device.tilesByRank},   // under mpirun (docs/scale.md); empty otherwise
        {"tiles_by_device", device.tilesByDevice},   // over --devices (docs/multi_gpu.md); empty otherwise
        {"rays_per_second", counters.seconds > 0 ? double(counters.rays) / counters.seconds : 0.0},
        // The scene as a scene file has it (its order dropped: the stats' object sorts its keys).
        {"scene", nlohmann::json(sceneToJson(o.scene))},
    };
    if (device.photons) {
        const PhotonTimings& p = *device.photons;
        stats["photons"] = {{"seconds", {{"flags", p.flags}, {"photons", p.photons}, {"grid", p.grid}, {"camera", p.camera},
                                         {"lighting_pass", p.lightingPass}}},
                            {"photon_rays", p.photonRays}, {"stored", p.stored}, {"texels", p.texels},
                            {"blocks", p.blocks}, {"blocks_with_memory", p.blocksWithMemory}};
    }
    writeTextFileAtomically(o.run.statsFile, stats.dump(2) + "\n");
}

} // namespace

void runRender(const RenderOptions& o, const MpiWorld* world) {
    const auto start = SteadyClock::now();
    const RunOptions& run = o.run;
    const FilmDescription& film = o.scene.film;
    size_t threads = run.threads ? run.threads : size_t(tbb::info::default_concurrency());
    tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism, threads);
    const bool animated = !o.frames.frames.empty();
    if (animated) checkFrameOptions(o);   // and makes the frames' folder, which the check below needs
    else if (!o.frames.video.empty() || o.frames.overwrite)
        throw InputError(std::string(o.frames.overwrite ? "--overwrite" : "--video") + ": needs --frames", FailureKind::Usage);
    checkOutputPath("--out", film.output, {".png", ".exr"});
    checkOutputPath("--stats", run.statsFile, {".json"});
    checkOutputPath("--save-scene", o.saveSceneFile, {".json"});
    checkDistinctOutputs("--out", film.output, "--stats", run.statsFile);
    checkDistinctOutputs("--out", film.output, "--save-scene", o.saveSceneFile);
    checkDistinctOutputs("--stats", run.statsFile, "--save-scene", o.saveSceneFile);
    const size_t limit = memoryLimit(run.maxMemory);
    const uint32_t layers = filmLayerMaskOf(film.layers);
    // The denoiser is guided by the AOVs: it needs the AOV pass whatever the output.
    const bool aovs = film.denoise || filmOutputNeedsAovs(film.output, layers);
    requireMemory(hostFilmBytes(film.width, film.height, filmOutputNeedsAovs(film.output, layers), film.denoise), limit,
                  "the " + std::to_string(film.width) + "x" + std::to_string(film.height) + " image");

    const std::vector<int> gpus = devicesOf(run.devices, run.device);
    if (!gpus.empty() && world && world->ranks() > 1)
        throw InputError("--devices under mpirun: each rank takes the GPU of its local rank (--device cuda; docs/multi_gpu.md)",
                         FailureKind::Usage);
    PreparedScene prepared = prepareScene(o.scene, run.strict, limit);
    // Written once the input has proved good, before the render's time is spent.
    const bool writes = !world || world->isRoot();
    if (writes && !o.saveSceneFile.empty()) writeSceneFile(o.scene, o.saveSceneFile);
    if (animated) {
        renderFrames(o, prepared, gpus, world);
        return;
    }
    const RenderSettings settings = renderSettingsOf(o.scene);
    RenderCounters counters;
    DeviceReport device;
    Film image(settings.width, settings.height, aovs);
    const RendererOptions where{gpus.empty() ? run.device : "cuda", gpus, Film::bytesFor(image.width, image.height, aovs),
                                run.verbose, world};
    Renderer::make(prepared.scene, settings.integrator, where)
        ->render(prepared.camera, settings, image.nextSamples(settings.spp), image, film.denoise, isatty(2), counters, device);
    if (!writes) return;

    auto t0 = SteadyClock::now();
    writeFilm(image, film.output, FilmOutputOptions{film.exposure, film.exrFloat, layers});
    double secondsWrite = secondsSince(t0);

    if (!run.statsFile.empty()) writeStats(o, prepared, settings, counters, device, threads, secondsWrite);
    std::string also;
    for (const std::string* file : {&run.statsFile, &o.saveSceneFile})
        if (!file->empty()) also += " and " + *file;
    std::printf("urbis: wrote %s (%ux%u, %u spp, %s)%s in %.2f s\n", film.output.c_str(), settings.width,
                settings.height, settings.spp, device.device.c_str(), also.c_str(), secondsSince(start));
}

} // namespace urbis
