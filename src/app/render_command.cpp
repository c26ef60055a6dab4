#include "app/render_command.h"

#include "app/camera_checks.h"
#include "app/memory_json.h"
#include "app/memory_limit.h"
#include "app/option_parsing.h"
#include "app/output_paths.h"
#include "app/render_device.h"
#include "citygen/city_mesher.h"
#include "cpu/cpu_renderer.h"
#include "film/film_output.h"
#include "io/atomic_file.h"
#include "layout/city_layout.h"
#include "base/input_error.h"
#include "lights/light_build.h"
#include "osm/geo_projection.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace urbis {

void addRenderCommand(CLI::App& app, RenderOptions& o) {
    CLI::App* cmd = app.add_subcommand("render", "Path trace a city to a PNG or EXR (the generated default world without --osm)");
    cmd->add_option("--osm", o.osmFile, "OpenStreetMap file: .osm, .osm.pbf, .osm.bz2, .osm.gz");
    cmd->add_option("--out", o.outFile, "Image to write; the format follows the extension: .png (tone-mapped sRGB) or "
                                        ".exr (linear RGBA with albedo, normal, depth, position, id and sample layers)")
        ->capture_default_str();
    cmd->add_flag("--exr-float", o.exrFloat, "EXR colour, albedo and normal as 32-bit float (default half)");
    cmd->add_option("--width", o.settings.width, "Image width in pixels")->check(CLI::Range(1u, kMaxImageSide))->capture_default_str();
    cmd->add_option("--height", o.settings.height, "Image height in pixels")->check(CLI::Range(1u, kMaxImageSide))->capture_default_str();
    cmd->add_option("--spp", o.settings.spp, "Samples per pixel")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    cmd->add_option("--seed", o.settings.seed, "Seed of the city and of the sampler")->capture_default_str();
    cmd->add_option("--threads", o.threads, "CPU threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
    cmd->add_option("--buildings", o.buildings, "Buildings in the generated city")->check(CLI::Range(uint64_t(1), uint64_t(5000000)))->capture_default_str();
    const LayoutParams layout;
    cmd->add_option("--building-height-range", o.heightRange,
                    "MIN:MAX metres, seeded uniform, for OSM buildings without height or levels tags (without it "
                    "their heights are estimated from tagged neighbours of their type and a table of types) and "
                    "for the generated city (default " + std::to_string(int(layout.minBuildingHeight)) + ":" +
                        std::to_string(int(layout.maxBuildingHeight)) + ")");
    cmd->add_option("--metres-per-level", o.metresPerLevel, "Storey height for building:levels")->check(CLI::Range(1.0, 20.0))->capture_default_str();
    cmd->add_option("--bbox", o.bbox, "Crop OSM to MINLON,MINLAT,MAXLON,MAXLAT (default: the file's header box)");
    cmd->add_option("--camera", o.camera, "X,Y,Z,TX,TY,TZ: position and target in world metres (x east, y up, z south)");
    cmd->add_option("--camera-geo", o.cameraGeo, "LON,LAT,ALTITUDE,HEADING,PITCH (OSM only; degrees, metres)");
    cmd->add_option("--fov", o.fovDeg, "Vertical field of view, degrees")->check(CLI::Range(1.0, 170.0))->capture_default_str();
    cmd->add_option("--sun", o.sun, "ELEVATION,AZIMUTH of the sun in degrees (azimuth clockwise from north)")->capture_default_str();
    cmd->add_option("--sun-radius", o.sunRadiusDeg, "Angular radius of the sun, degrees")->check(CLI::Range(0.01, 20.0))->capture_default_str();
    cmd->add_option("--exposure", o.exposureEv, "Exposure in stops")->check(CLI::Range(-20.0, 20.0))->capture_default_str();
    cmd->add_option("--max-depth", o.settings.maxDepth, "Path vertices after the camera")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--rr-depth", o.settings.rrDepth, "Depth where Russian roulette starts")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--rr-survival", o.settings.rrSurvival, "Largest survival probability of Russian roulette")->check(CLI::Range(0.01, 1.0))->capture_default_str();
    cmd->add_option("--geometry", o.geometry,
                    "procedural|triangles|plain for every kind, or KIND=MODE,... (kinds: walls, roofs, buildings); plain: no facades")
        ->capture_default_str();
    cmd->add_option("--height-scale", o.heightScale, "Multiply every building's height (and min height)")
        ->check(CLI::Range(0.05, 50.0))
        ->capture_default_str();
    cmd->add_option("--wall-tiles", o.wallTiles,
                    "whole, or SLOTSxFLOORS: split each procedural wall into BVH tiles of at most that many cells")
        ->capture_default_str();
    cmd->add_option("--stats", o.statsFile, "Write counts, memory, timings and rays/s as JSON (a .json file)");
    cmd->add_option("--device", o.device, "auto (the GPU if usable, else the CPU), cpu or cuda")
        ->check(CLI::IsMember({"auto", "cpu", "cuda"}))->capture_default_str();
    addRunOptions(*cmd, o);
}

void addRunOptions(CLI::App& cmd, RenderOptions& o) {
    cmd.add_option("--max-memory", o.maxMemory,
                   "Host memory the run may take, e.g. 8G, 512M, 2000000000 (default: 80 % of the memory available)");
    cmd.add_flag("--strict", o.strict, "Treat warnings (a camera inside a building, underground or far away) as errors");
    cmd.add_flag("--verbose", o.verbose, "Say which device renders and why");
}

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// The height range for untagged buildings from "MIN:MAX", if given.
bool parseHeightRange(const std::string& text, float& lo, float& hi) {
    if (text.empty()) return false;
    std::vector<double> v = parseNumberList("--building-height-range", text, ':', 2, 2);
    if (!(v[0] >= 0.0 && v[0] <= v[1] && v[1] <= 1000.0))
        throw InputError("--building-height-range: need 0 <= MIN <= MAX <= 1000 metres, got '" + text + "'", FailureKind::Usage);
    lo = float(v[0]);
    hi = float(v[1]);
    return true;
}

CityModel loadCity(const RenderOptions& o) {
    std::optional<std::array<double, 4>> bbox = parseBbox(o.bbox);
    if (o.osmFile.empty()) {
        if (bbox) throw InputError("--bbox: crops an OSM file and needs --osm", FailureKind::Usage);
        LayoutParams params;
        params.buildings = o.buildings;
        params.seed = o.settings.seed;
        parseHeightRange(o.heightRange, params.minBuildingHeight, params.maxBuildingHeight);
        return generateCity(params);
    }
    ImportOptions params;
    params.seed = o.settings.seed;
    params.metresPerLevel = o.metresPerLevel;
    if (float lo = 0, hi = 0; parseHeightRange(o.heightRange, lo, hi)) params.untaggedHeightRange = {{lo, hi}};
    params.bbox = bbox;
    return importOsm(o.osmFile, params);
}

/// Scales every building's heights by --height-scale.
void scaleHeights(CityModel& city, float scale) {
    if (scale == 1.0f) return;
    for (Building& b : city.buildings) {
        b.height *= scale;
        b.minHeight *= scale;
        b.roofHeight *= scale;
    }
}

Camera chooseCamera(const RenderOptions& o, const CityModel& city, const CityMesh& mesh) {
    float aspect = float(o.settings.width) / float(o.settings.height);
    if (!o.camera.empty()) {
        std::vector<double> c = parseNumberList("--camera", o.camera, ',', 6, 6);
        return makeLookAtCamera(Vec3f{float(c[0]), float(c[1]), float(c[2])}, Vec3f{float(c[3]), float(c[4]), float(c[5])},
                                o.fovDeg, aspect);
    }
    if (!o.cameraGeo.empty()) {
        if (!city.origin.valid) throw InputError("--camera-geo: needs a city imported with --osm", FailureKind::Usage);
        std::vector<double> c = parseNumberList("--camera-geo", o.cameraGeo, ',', 5, 5);
        Vec2d local = GeoProjection(LonLat{city.origin.lon, city.origin.lat}).project(LonLat{c[0], c[1]});
        return cameraFromHeading(Vec3f{float(local.x), float(c[2]), float(-local.y)}, float(c[3]), float(c[4]),
                                 o.fovDeg, aspect);
    }
    return frameCity(mesh.framingPieces, o.fovDeg, aspect);
}

/// Says on stderr what is wrong with the camera, or with --strict fails on the first problem.
void checkCamera(const RenderOptions& o, const Camera& camera, const CityModel& city, const Bounds3f& cityBounds) {
    for (const std::string& problem : cameraProblems(camera, city, cityBounds)) {
        if (o.strict) throw InputError(problem + " (--strict)", FailureKind::Usage);
        std::fprintf(stderr, "urbis: warning: %s\n", problem.c_str());
    }
}

Sun daySun(const RenderOptions& o) {
    std::vector<double> s = parseNumberList("--sun", o.sun, ',', 2, 2);
    if (!(s[0] >= -90.0 && s[0] <= 90.0)) throw InputError("--sun: elevation must be in [-90, 90] degrees", FailureKind::Usage);
    // Irradiance in the renderer's relative units: about six times the analytic sky's.
    return makeSun(float(s[0]), float(s[1]), o.sunRadiusDeg, Vec3f{3.3f, 3.1f, 2.8f});
}

nlohmann::json countsJson(const CityModel& city) {
    double heights = 0;
    for (const Building& b : city.buildings) heights += b.height;
    return {{"buildings", city.buildings.size()},
            {"mean_building_height", city.buildings.empty() ? 0.0 : heights / double(city.buildings.size())}, {"building_parts", city.buildingParts()},
            {"roads", city.roads.size()}, {"lamps", city.lamps.size()}, {"trees", city.trees.size()},
            {"areas", city.areas.size()}};
}

/// --wall-tiles as a tile size ({0, 0}: whole walls).
WallTileSize wallTileSize(const std::string& text) {
    if (text == "whole") return {};
    WallTileSize size;
    char x = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &size.slots, &x, &size.floors, &rest) != 3 || x != 'x' ||
        size.slots < 1 || size.floors < 1 || size.slots > 0xffff || size.floors > 0xffff)
        throw InputError("--wall-tiles: need 'whole' or SLOTSxFLOORS (e.g. 4x4), got '" + text + "'", FailureKind::Usage);
    return size;
}

} // namespace

PreparedScene prepareScene(const RenderOptions& o, size_t memoryLimit) {
    PreparedScene p;
    Sun sun = daySun(o);
    const WallTileSize tileSize = wallTileSize(o.wallTiles);
    CityMeshOptions meshOptions;
    meshOptions.geometry = p.geometry = parseGeometryModes(o.geometry);
    meshOptions.memoryLimit = memoryLimit;
    auto t0 = Clock::now();
    p.city = loadCity(o);
    scaleHeights(p.city, o.heightScale);
    p.secondsImport = secondsSince(t0);

    t0 = Clock::now();
    p.mesh = meshCity(p.city, meshOptions);
    p.secondsCitygen = secondsSince(t0);

    t0 = Clock::now();
    const Vec3f centre = p.mesh.cityBounds.empty() ? Vec3f{} : p.mesh.cityBounds.centre();
    p.scene = Scene::build(p.mesh.mesh, p.mesh.materials, p.mesh.walls, tileSize,
                           {GroundRecord::around(centre.x, centre.z, 0.0f, p.mesh.groundMaterial)});
    p.scene.sun = sun;
    buildLights(p.scene);
    p.secondsBvh = secondsSince(t0);

    p.camera = chooseCamera(o, p.city, p.mesh);
    checkCamera(o, p.camera, p.city, p.mesh.cityBounds);
    return p;
}

namespace {

/// Writes --stats: counts, what was dropped and repaired, memory, timings and rays/s.
void writeStats(const RenderOptions& o, const PreparedScene& prepared, const RenderCounters& counters,
                const DeviceReport& device, size_t threads, double secondsWrite) {
    const CityModel& city = prepared.city;
    const CityMesh& cityMesh = prepared.mesh;
    const Scene& scene = prepared.scene;
    SceneMemory memory = scene.memory();
    // Import and meshing use their own reasons (docs/cli.md); the meshed roofs' fallbacks count as repairs.
    nlohmann::json dropped(cityMesh.dropped), repaired = nlohmann::json::object();
    for (const auto& [reason, entry] : city.dropped) dropped[reason] = dropped.value(reason, uint64_t(0)) + entry.count;
    for (const auto& [reason, entry] : city.repaired) repaired[reason] = entry.count;
    for (const auto& [reason, n] : cityMesh.roofFallbacks) repaired["roof_" + reason] = n;
    if (cityMesh.holesDropped) repaired["footprint_hole_dropped"] = cityMesh.holesDropped;
    nlohmann::json stats = {
        {"source", city.source},
        {"counts", countsJson(city)},
        {"dropped", dropped},
        {"repaired", repaired},
        {"triangles", scene.triangles.size()},
        {"triangles_by_kind", cityMesh.trianglesByKind},
        {"geometry", {{"walls", representationName(prepared.geometry.walls)},
                      // Of the roofs only the parapets are procedural; plain roofs are stored triangles.
                      {"roofs", representationName(prepared.geometry.roofs == Representation::Procedural
                                                       ? Representation::Procedural
                                                       : Representation::Triangles)}}},
        {"walls", scene.walls.empty() ? size_t(0) : cityMesh.facadeWalls},
        {"wall_tiles", scene.walls.size()},
        {"wall_tile_size", o.wallTiles},
        {"facade_walls", cityMesh.facadeWalls},
        {"facade_cells", cityMesh.facadeCells},
        {"bvh_nodes", scene.nodes.size()},
        {"materials", scene.materials.size()},
        {"bytes_scene", memory.total()},
        {"bytes_by_kind", memoryJson(memory)},
        {"width", o.settings.width}, {"height", o.settings.height}, {"spp", o.settings.spp},
        {"seed", o.settings.seed}, {"threads", threads}, {"device", device.device},
        {"device_name", device.name},
        {"bytes_device", memoryJson(device.memory)},
        {"seconds", {{"import", prepared.secondsImport}, {"citygen", prepared.secondsCitygen}, {"bvh", prepared.secondsBvh},
                     {"render", counters.seconds}, {"write", secondsWrite}}},
        {"seconds_render", counters.seconds},
        {"rays", counters.rays},
        {"rays_per_second", counters.seconds > 0 ? double(counters.rays) / counters.seconds : 0.0},
    };
    writeTextFileAtomically(o.statsFile, stats.dump(2) + "\n");
}

} // namespace

void runRender(const RenderOptions& o) {
    const auto start = Clock::now();
    size_t threads = o.threads ? o.threads : size_t(tbb::info::default_concurrency());
    tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism, threads);
    checkOutputPath("--out", o.outFile, {".png", ".exr"});
    checkOutputPath("--stats", o.statsFile, {".json"});
    checkDistinctOutputs("--out", o.outFile, "--stats", o.statsFile);
    const size_t limit = memoryLimit(o.maxMemory);
    const bool aovs = filmOutputNeedsAovs(o.outFile);
    requireMemory(hostFilmBytes(o.settings.width, o.settings.height, aovs), limit,
                  "the " + std::to_string(o.settings.width) + "x" + std::to_string(o.settings.height) + " image");

    PreparedScene prepared = prepareScene(o, limit);
    RenderCounters counters;
    DeviceReport device;
    Film film(o.settings.width, o.settings.height, aovs);
    renderOnDevice(prepared.scene, prepared.camera, o.settings, film.nextSamples(o.settings.spp), film, o.device,
                   isatty(2), o.verbose, counters, device);

    auto t0 = Clock::now();
    writeFilm(film, o.outFile, FilmOutputOptions{o.exposureEv, o.exrFloat});
    double secondsWrite = secondsSince(t0);

    if (!o.statsFile.empty()) writeStats(o, prepared, counters, device, threads, secondsWrite);
    std::printf("urbis: wrote %s (%ux%u, %u spp, %s)%s in %.2f s\n", o.outFile.c_str(), o.settings.width,
                o.settings.height, o.settings.spp, device.device.c_str(),
                o.statsFile.empty() ? "" : (" and " + o.statsFile).c_str(), secondsSince(start));
}

} // namespace urbis
