#include "app/scene_options.h"

#include "app/option_parsing.h"
#include "astro/civil_time.h"
#include "description/scene_checks.h"
#include "description/scene_json.h"
#include "layout/city_layout.h"
#include "base/input_error.h"

#include <algorithm>
#include <cstdio>

namespace urbis {

namespace {

Vec3f vec3Of(const std::vector<double>& v, size_t first) {
    return Vec3f{float(v[first]), float(v[first + 1]), float(v[first + 2])};
}

} // namespace

SceneCommandLine::SceneCommandLine(SceneDescription defaults) : defaults_(std::move(defaults)), values_(defaults_) {}

bool SceneCommandLine::wanted(std::string_view name) const {
    return only_.empty() || std::find(only_.begin(), only_.end(), name) != only_.end();
}

template <typename T, typename Apply>
CLI::Option* SceneCommandLine::bind(CLI::App& cmd, const std::string& name, T& storage, const std::string& help,
                                    Apply apply) {
    if (!wanted(name)) return nullptr;
    CLI::Option* option = cmd.add_option(name, storage, help);
    overrides_.emplace_back(option, [&storage, apply](SceneDescription& d) { apply(d, storage); });
    return option;
}

void SceneCommandLine::addOptions(CLI::App& cmd, std::initializer_list<std::string_view> only) {
    only_.assign(only.begin(), only.end());
    cmd.add_option("--scene", sceneFile_,
                   "Scene file (.json, docs/scene_files.md) to render; the options given here override its keys");
    cmd.add_option("--save-scene", saveScene_,
                   "Write the scene this command amounts to (every key) to a .json file, then go on");
    SceneDescription& v = values_;
    const auto range = [](CLI::Option* option, auto lo, auto hi) {
        if (option) option->check(CLI::Range(lo, hi))->capture_default_str();
    };
    const auto withDefault = [](CLI::Option* option) {
        if (option) option->capture_default_str();
    };

    // source
    bind(cmd, "--osm", v.source.osm, "OpenStreetMap file: .osm, .osm.pbf, .osm.bz2, .osm.gz (default: the generated city)",
         [](SceneDescription& d, const std::string& osm) { d.source.osm = osm; });
    bind(cmd, "--bbox", text_.bbox, "Crop OSM to MINLON,MINLAT,MAXLON,MAXLAT (default: the file's header box)",
         [](SceneDescription& d, const std::string& text) { d.source.bbox = parseBbox(text); });
    const LayoutParams layout;
    bind(cmd, "--building-height-range", text_.heightRange,
         "MIN:MAX metres, seeded uniform, for OSM buildings without height or levels tags (without it their heights "
         "are estimated from tagged neighbours of their type and a table of types) and for the generated city (default " +
             std::to_string(int(layout.minBuildingHeight)) + ":" + std::to_string(int(layout.maxBuildingHeight)) + ")",
         [](SceneDescription& d, const std::string& text) {
             std::vector<double> r = parseNumberList("--building-height-range", text, ':', 2, 2);
             if (!(r[0] >= 0.0 && r[0] <= r[1] && r[1] <= 1000.0))
                 throw InputError("--building-height-range: need 0 <= MIN <= MAX <= 1000 metres, got '" + text + "'",
                                  FailureKind::Usage);
             d.source.heightRange = std::array<float, 2>{float(r[0]), float(r[1])};
         });
    range(bind(cmd, "--metres-per-level", v.source.metresPerLevel, "Storey height for building:levels",
               [](SceneDescription& d, float m) { d.source.metresPerLevel = m; }),
          1.0, 20.0);
    range(bind(cmd, "--height-scale", v.source.heightScale, "Multiply every building's height (and min height)",
               [](SceneDescription& d, float s) { d.source.heightScale = s; }),
          0.05, 50.0);
    range(bind(cmd, "--buildings", v.source.buildings, "Buildings in the generated city",
               [](SceneDescription& d, uint64_t n) { d.source.buildings = n; }),
          uint64_t(1), kMaxDescribedBuildings);
    withDefault(bind(cmd, "--seed", v.integrator.seed, "Seed of the city and of the sampler",
                     [](SceneDescription& d, uint32_t seed) { d.source.seed = d.integrator.seed = seed; }));

    // camera
    bind(cmd, "--camera", text_.camera, "X,Y,Z,TX,TY,TZ: position and target in world metres (x east, y up, z south)",
         [](SceneDescription& d, const std::string& text) {
             std::vector<double> c = parseNumberList("--camera", text, ',', 6, 6);
             d.camera.position = vec3Of(c, 0);
             d.camera.target = vec3Of(c, 3);
             d.camera.geo.reset();
         });
    CLI::Option* geo =
        bind(cmd, "--camera-geo", text_.cameraGeo,
             "LON,LAT,ALTITUDE,HEADING,PITCH (OSM only; degrees, metres above y = 0, sea level on a DEM; "
             "ALTITUDE with the suffix agl, as 50agl: metres above the terrain under the camera)",
             [](SceneDescription& d, const std::string& text) {
                 // ALTITUDE may end in "agl" (above ground level): the third field, before its comma.
                 std::string numbers = text;
                 size_t third = numbers.find(',');
                 if (third != std::string::npos) third = numbers.find(',', third + 1);
                 const size_t end = third == std::string::npos ? std::string::npos : numbers.find(',', third + 1);
                 const bool agl = end != std::string::npos && end >= third + 4 && numbers.compare(end - 3, 3, "agl") == 0;
                 if (agl) numbers.erase(end - 3, 3);
                 std::vector<double> c = parseNumberList("--camera-geo", numbers, ',', 5, 5);
                 d.camera.geo = GeoCameraDescription{c[0], c[1], float(c[2]), float(c[3]), float(c[4]), agl};
                 d.camera.position.reset();
                 d.camera.target.reset();
             });
    if (geo && cmd.get_option_no_throw("--camera")) geo->excludes("--camera");
    range(bind(cmd, "--fov", v.camera.fov, "Vertical field of view, degrees",
               [](SceneDescription& d, float fov) { d.camera.fov = fov; }),
          1.0, 170.0);
    range(bind(cmd, "--fps", v.animation.fps, "Frames per second of the scene's animation (docs/animation.md)",
               [](SceneDescription& d, float fps) { d.animation.fps = fps; }),
          0.01, 1000.0);

    // date, time and place; registered before --sun, whose angles override the time's sun
    bind(cmd, "--time", text_.time,
         "ISO 8601 date and time with a UTC offset or Z (2024-06-21T20:30+02:00): sets the sun, the moon and the stars",
         [](SceneDescription& d, const std::string& text) {
             std::string error;
             if (!parseIsoTime(text, error)) throw InputError("--time: '" + text + "': " + error, FailureKind::Usage);
             d.astronomy.time = text;
             d.astronomy.sunFromTime = true;
         });
    char place[48];
    std::snprintf(place, sizeof place, "%.4f,%.4f", kDefaultLocation[0], kDefaultLocation[1]);
    bind(cmd, "--location", text_.location,
         std::string("LON,LAT in degrees the sky is seen from (default: the OSM extract's centre; the generated city: "
                     "Prague, ") + place + ")",
         [](SceneDescription& d, const std::string& text) { d.astronomy.location = parseLocation("--location", text); });

    // sun
    text_.sun = std::to_string(int(v.sun.elevation)) + "," + std::to_string(int(v.sun.azimuth));
    withDefault(bind(cmd, "--sun", text_.sun, "ELEVATION,AZIMUTH of the sun in degrees (azimuth clockwise from north)",
                     [](SceneDescription& d, const std::string& text) {
                         std::vector<double> s = parseNumberList("--sun", text, ',', 2, 2);
                         if (!(s[0] >= -90.0 && s[0] <= 90.0))
                             throw InputError("--sun: elevation must be in [-90, 90] degrees", FailureKind::Usage);
                         if (!(s[1] >= -360.0 && s[1] <= 360.0))
                             throw InputError("--sun: azimuth must be in [-360, 360] degrees", FailureKind::Usage);
                         d.sun.elevation = float(s[0]);
                         d.sun.azimuth = float(s[1]);
                         d.astronomy.sunFromTime = false;
                     }));
    if (wanted("--no-aerial-perspective")) {
        CLI::Option* flag = cmd.add_flag("--no-aerial-perspective", noAerialPerspective_,
                                         "No haze along path segments (the atmosphere still gives the sky and the sun)");
        overrides_.emplace_back(flag, [](SceneDescription& d) { d.sky.aerialPerspective = false; });
    }
    if (CLI::Option* sky = bind(cmd, "--sky", v.sky.model, "Sky model: atmosphere (Hillaire 2020) or analytic (a gradient)",
                                [](SceneDescription& d, const std::string& s) { d.sky.model = s; }))
        sky->check(CLI::IsMember(std::vector<std::string>(std::begin(kSkyModels), std::end(kSkyModels))))->capture_default_str();
    range(bind(cmd, "--sun-radius", v.sun.angularRadius, "Angular radius of the sun, degrees",
               [](SceneDescription& d, float r) { d.sun.angularRadius = r; }),
          0.01, 20.0);
    range(bind(cmd, "--clouds", v.clouds.layer.coverage,
               "Cloud coverage, 0 (none) to 1 (overcast); the layer's other parameters are the scene file's `clouds`",
               [](SceneDescription& d, float c) { d.clouds.layer.coverage = c; }),
          0.0, 1.0);

    // geometry
    text_.geometry = "procedural";
    withDefault(bind(cmd, "--geometry", text_.geometry,
                     "procedural|triangles|plain for every kind, or KIND=MODE,... (kinds: walls, roofs, lamps, trees, buildings); "
                     "plain: no facades",
                     [](SceneDescription& d, const std::string& text) { d.geometry.modes = parseGeometryModes(text); }));
    withDefault(bind(cmd, "--wall-tiles", v.geometry.wallTiles,
                     "whole, or SLOTSxFLOORS: split each procedural wall into BVH tiles of at most that many cells",
                     [](SceneDescription& d, const std::string& text) {
                         if (!wallTileSizeOf(text))
                             throw InputError("--wall-tiles: need 'whole' or SLOTSxFLOORS (e.g. 4x4), got '" + text + "'",
                                              FailureKind::Usage);
                         d.geometry.wallTiles = text;
                     }));
    if (CLI::Option* traffic = bind(cmd, "--traffic", v.geometry.traffic,
                                    "The side traffic keeps (lanes, stop lines): auto (by the city's place), right or left",
                                    [](SceneDescription& d, const std::string& s) { d.geometry.traffic = s; }))
        traffic->check(CLI::IsMember(std::vector<std::string>(std::begin(kTrafficSides), std::end(kTrafficSides))))
            ->capture_default_str();
    if (wanted("--no-streets")) {
        CLI::Option* flag = cmd.add_flag("--no-streets", noStreets_, "Buildings on the bare ground: no roads, sidewalks, ground cover, water, lamps or trees");
        overrides_.emplace_back(flag, [](SceneDescription& d) { d.geometry.streets = false; });
    }

    // integrator
    range(bind(cmd, "--spp", v.integrator.spp, "Samples per pixel",
               [](SceneDescription& d, uint32_t spp) { d.integrator.spp = spp; }),
          1u, kMaxSpp);
    range(bind(cmd, "--max-depth", v.integrator.maxDepth, "Path vertices after the camera",
               [](SceneDescription& d, uint32_t n) { d.integrator.maxDepth = n; }),
          1u, 1000u);
    range(bind(cmd, "--rr-depth", v.integrator.rrDepth, "Depth where Russian roulette starts",
               [](SceneDescription& d, uint32_t n) { d.integrator.rrDepth = n; }),
          1u, 1000u);
    range(bind(cmd, "--rr-survival", v.integrator.rrSurvival, "Largest survival probability of Russian roulette",
               [](SceneDescription& d, float p) { d.integrator.rrSurvival = p; }),
          0.01, 1.0);
    if (CLI::Option* sampler = bind(cmd, "--light-sampler", v.integrator.lightSampler, "How lights are picked: uniform, power, bvh (the light BVH) or colliders (the thesis's)",
                                    [](SceneDescription& d, const std::string& s) { d.integrator.lightSampler = s; }))
        sampler->check(CLI::IsMember(std::vector<std::string>(std::begin(kLightSamplers), std::end(kLightSamplers))))
            ->capture_default_str();
    if (CLI::Option* kind = bind(cmd, "--integrator", v.integrator.kind, "path (the path tracer), photon-buffers (indirect light from per-block photon buffers) or photon-map (from a hash-grid photon map, the reference)",
                                 [](SceneDescription& d, const std::string& s) { d.integrator.kind = s; }))
        kind->check(CLI::IsMember(std::vector<std::string>(std::begin(kIntegratorKinds), std::end(kIntegratorKinds))))
            ->capture_default_str();
    range(bind(cmd, "--photons", v.photons.perPass, "Photons per pass of the photon integrators (one pass per sample)",
               [](SceneDescription& d, uint32_t n) { d.photons.perPass = n; }),
          1u, 1u << 26);
    range(bind(cmd, "--photon-radius", v.photons.radius, "Metres: the photon map's gather radius at the first pass",
               [](SceneDescription& d, float r) { d.photons.radius = r; }),
          1e-3, 1e3);

    // film
    withDefault(bind(cmd, "--out", v.film.output, "Image to write; the format follows the extension: .png (tone-mapped sRGB) or .exr (linear, with AOV layers)",
                     [](SceneDescription& d, const std::string& out) { d.film.output = out; }));
    range(bind(cmd, "--width", v.film.width, "Image width in pixels",
               [](SceneDescription& d, uint32_t w) { d.film.width = w; }),
          1u, kMaxImageSide);
    range(bind(cmd, "--height", v.film.height, "Image height in pixels",
               [](SceneDescription& d, uint32_t h) { d.film.height = h; }),
          1u, kMaxImageSide);
    range(bind(cmd, "--exposure", v.film.exposure, "Exposure in stops",
               [](SceneDescription& d, float ev) { d.film.exposure = ev; }),
          -20.0, 20.0);
    if (wanted("--exr-float")) {
        CLI::Option* flag = cmd.add_flag("--exr-float", v.film.exrFloat, "EXR colour, albedo and normal as 32-bit float (default half)");
        overrides_.emplace_back(flag, [&v](SceneDescription& d) { d.film.exrFloat = v.film.exrFloat; });
    }
    if (wanted("--denoise")) {
        CLI::Option* flag = cmd.add_flag("--denoise", v.film.denoise, "Denoise the HDR film, guided by its AOVs, before it is written");
        overrides_.emplace_back(flag, [&v](SceneDescription& d) { d.film.denoise = v.film.denoise; });
    }
    addTerrainOptions(cmd);

    // a whole planet instead of the city (docs/planets.md)
    if (CLI::Option* planet = bind(cmd, "--planet", text_.planet,
                                   "[RADIUS_KM]: render a whole planet instead of the city (default Earth-like, 6360 km, "
                                   "or the scene file's planet)",
                                   [](SceneDescription& d, const std::string& text) {
                                       if (!d.planet) d.planet = PlanetDescription{};
                                       if (text.empty()) return;
                                       const double r = parseNumberList("--planet", text, ',', 1, 1)[0];
                                       if (!(r >= 10.0 && r <= 1e6))
                                           throw InputError("--planet: radius must be in [10, 1e6] km, got '" + text + "'",
                                                            FailureKind::Usage);
                                       d.planet->radiusKm = r;
                                   }))
        planet->expected(0, 1);
    bind(cmd, "--camera-orbit", text_.cameraOrbit,
         "ALT_KM,LAT,LON[,HEADING,PITCH]: the camera above a planet (--planet): km above the ground under it, degrees "
         "(heading clockwise from north, pitch above the horizon; default 0,-90: straight down)",
         [](SceneDescription& d, const std::string& text) {
             if (!d.planet) throw InputError("--camera-orbit: places the camera above a planet and needs --planet", FailureKind::Usage);
             const std::vector<double> c = parseNumberList("--camera-orbit", text, ',', 3, 5);
             if (!(c[0] >= 0.0 && c[0] <= 1e6 && c[1] >= -90.0 && c[1] <= 90.0 && c[2] >= -360.0 && c[2] <= 360.0))
                 throw InputError("--camera-orbit: need 0 <= ALT_KM <= 1e6, LAT in [-90, 90], LON in [-360, 360], got '" +
                                      text + "'", FailureKind::Usage);
             PlanetCameraDescription& camera = d.planet->camera;
             camera = {c[0], c[1], c[2], c.size() > 3 ? float(c[3]) : 0.0f, c.size() > 4 ? float(c[4]) : -90.0f};
             if (!(camera.pitch >= -90.0f && camera.pitch <= 90.0f))
                 throw InputError("--camera-orbit: PITCH must be in [-90, 90] degrees", FailureKind::Usage);
         });
}

SceneDescription SceneCommandLine::resolve() const {
    SceneDescription d = sceneFile_.empty() ? defaults_ : readSceneFile(sceneFile_);
    for (const auto& [option, apply] : overrides_)
        if (option->count()) apply(d);
    // The file alone was checked as it was read: what fails here, the command line's options made.
    if (std::optional<SceneProblem> problem = firstSceneProblem(d))
        throw InputError(problem->option + " (" + problem->key + "): " + problem->message, FailureKind::Usage);
    return d;
}

} // namespace urbis
