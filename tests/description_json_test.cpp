// Scene files as JSON: every key written, read back to the same description, every problem named
// by its key path on one line.
#include "cli_support.h"
#include "description/scene_checks.h"
#include "description/scene_json.h"
#include "base/input_error.h"

#include <gtest/gtest.h>

#include <functional>
#include <set>

using namespace urbis;
using nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

/// Every key path of the JSON form ("film.width"), objects' own paths included.
void collectKeys(const ordered_json& j, const std::string& prefix, std::set<std::string>& out) {
    for (const auto& [key, value] : j.items()) {
        const std::string path = prefix.empty() ? key : prefix + "." + key;
        out.insert(path);
        if (value.is_object()) collectKeys(value, path, out);
    }
}

/// A description with every field away from its default.
SceneDescription unusualScene() {
    SceneDescription d;
    d.source.osm = "/data/city.osm.pbf";
    d.source.bbox = std::array<double, 4>{-122.41, 37.78, -122.39, 37.80};
    d.source.heightRange = std::array<float, 2>{12.5f, 40.0f};
    d.source.metresPerLevel = 3.3f;
    d.source.heightScale = 1.7f;
    d.source.buildings = 1234;
    d.source.seed = 77;
    d.camera.geo = GeoCameraDescription{-122.397, 37.789, 300.0f, 20.0f, -25.0f};
    d.camera.fov = 35.5f;
    d.planet = PlanetDescription{3389.5, 150.0f, 6000.0f, 1234.5f, 0.55f, 17, 9, Vec3f{0.02f, 0.04f, 0.05f}, 0.3f,
                                 PlanetCameraDescription{0.002, -12.5, 77.25, 30.0f, 5.0f}};
    d.sun = SunDescription{12.0f, 270.0f, 0.5f, Vec3f{1.0f, 2.0f, 3.0f}};
    d.astronomy = AstronomyDescription{"2024-06-21T20:30+02:00", std::array<double, 2>{-122.4, 37.79}, false};
    d.sky = SkyDescription{Vec3f{0.1f, 0.2f, 0.3f}, Vec3f{0.4f, 0.5f, 0.6f}, Vec3f{0.7f, 0.8f, 0.9f}, 0.3f};
    d.materials.city.groundAlbedo = Vec3f{0.2f, 0.2f, 0.2f};
    d.materials.city.glassTransmittance = Vec3f{0.5f, 0.6f, 0.7f};
    d.materials.city.glassIor = 1.33f;
    d.materials.city.litRoomEmission = Vec3f{1.0f, 0.9f, 0.8f};
    d.materials.wallColourByType["office"] = Vec3f{0.3f, 0.3f, 0.35f};
    d.materials.roofColourByType["house"] = Vec3f{0.5f, 0.2f, 0.1f};
    d.geometry.modes = GeometryModes{Representation::Triangles, Representation::Plain};
    d.geometry.wallTiles = "4x2";
    d.integrator = IntegratorDescription{"path", 64, 9, 12, 4, 0.8f, "uniform"};
    d.film = FilmDescription{640, 480, 1.25f, "out/city.png", {"depth", "albedo"}};
    d.photons = PhotonsDescription{20000, 0.75f, 0.5f, 0.25f, 60.0f};
    return d;
}

/// The one line that reading `text` as "scene.json" fails with.
std::string problemOf(const std::string& text) {
    try {
        sceneFromJson(ordered_json::parse(text), "scene.json");
    } catch (const InputError& e) {
        EXPECT_EQ(e.kind(), FailureKind::BadInput) << e.what();
        return e.what();
    }
    return "no error";
}

} // namespace

TEST(DescriptionJson, SavedDefaultHasEveryKey) {
    std::set<std::string> keys;
    collectKeys(sceneToJson(SceneDescription{}), "", keys);
    const std::set<std::string> expected = {
        "source", "source.osm", "source.bbox", "source.height_range", "source.metres_per_level", "source.height_scale",
        "source.buildings", "source.seed",
        "camera", "camera.position", "camera.target", "camera.geo", "camera.fov",
        "sun", "sun.elevation", "sun.azimuth", "sun.angular_radius", "sun.irradiance",
        "astronomy", "astronomy.time", "astronomy.location", "astronomy.sun_from_time",
        "sky", "sky.zenith", "sky.horizon", "sky.ground", "sky.exponent", "sky.model", "sky.aerosols", "sky.ozone",
        "sky.mie_anisotropy", "sky.ground_albedo", "sky.altitude", "sky.aerial_perspective", "lights", "lights.hour",
        "materials", "materials.ground", "materials.ground.albedo", "materials.window_glass",
        "materials.window_glass.transmittance", "materials.window_glass.ior", "materials.lit_room",
        "materials.lit_room.emission", "materials.wall_colour_by_type", "materials.roof_colour_by_type",
        "geometry", "geometry.walls", "geometry.roofs", "geometry.lamps", "geometry.wall_tiles", "geometry.streets",
        "geometry.traffic",
        "integrator", "integrator.kind", "integrator.spp", "integrator.seed", "integrator.max_depth",
        "integrator.rr_depth", "integrator.rr_survival", "integrator.light_sampler", "integrator.light_samples",
        "film", "film.width", "film.height", "film.exposure", "film.output", "film.layers", "film.exr_float", "film.denoise",
        "photons", "photons.per_pass", "photons.radius", "photons.alpha", "photons.texel", "photons.level_distance", "planet",
        "clouds", "clouds.coverage", "clouds.type", "clouds.altitude", "clouds.thickness", "clouds.density",
        "clouds.albedo", "clouds.scale", "clouds.radius", "clouds.wind", "clouds.seed", "clouds.phase_forward",
        "clouds.phase_backward", "clouds.phase_blend", "clouds.octaves", "clouds.octave_scattering",
        "clouds.octave_extinction", "clouds.octave_anisotropy",
        "geometry.trees", "terrain", "terrain.kind", "terrain.dem", "terrain.march", "terrain.interpolation",
        "terrain.size", "terrain.cell", "terrain.detail", "terrain.fade", "terrain.fbm", "terrain.fbm.seed",
        "terrain.fbm.octaves", "terrain.fbm.wavelength", "terrain.fbm.amplitude", "terrain.fbm.lacunarity",
        "terrain.fbm.gain", "terrain.fbm.erosion", "terrain.fbm.warp", "terrain.fbm.offset", "terrain.dual", "terrain.dual.enabled",
        "terrain.dual.seed", "terrain.dual.wavelength", "terrain.dual.amplitude", "terrain.dual.offset",
        "terrain.dual.mask_wavelength", "terrain.materials",
        "terrain.materials.sand_level", "terrain.materials.snow_level", "terrain.materials.rock_slope",
        "terrain.lei", "terrain.lei.a", "terrain.lei.b", "terrain.lei.c", "terrain.lei.bisections",
        "terrain.reference_step", "water", "water.enabled", "water.max_depth", "water.shelf_width", "water.bank_slope", "water.absorption",
        "water.bed_albedo", "water.wind_speed", "water.wind_from", "trees", "trees.enabled", "trees.seed",
        "trees.forest_density", "trees.park_density", "trees.scrub_density", "trees.outer_forest", "trees.outer_forest_cell",
        "trees.outer_forest_density", "trees.clearance",
        "trees.default_height", "trees.size_variation", "trees.conifer_share", "trees.roughness", "trees.lumps",
        "trees.season", "trees.bark_albedo", "trees.leaf_albedo", "trees.needle_albedo", "trees.autumn_albedo",
        "animation", "animation.fps", "animation.duration", "animation.camera", "animation.time"};
    EXPECT_EQ(keys, expected);
    // The geographic camera's own keys, once it is set.
    SceneDescription geo;
    geo.camera.geo = GeoCameraDescription{};
    keys.clear();
    collectKeys(sceneToJson(geo), "", keys);
    for (const char* key : {"camera.geo.lon", "camera.geo.lat", "camera.geo.altitude", "camera.geo.heading", "camera.geo.pitch",
                            "camera.geo.above_ground"})
        EXPECT_TRUE(keys.count(key)) << key;
    // A planet's own keys, once it is set (docs/planets.md).
    SceneDescription planet;
    planet.planet = PlanetDescription{};
    keys.clear();
    collectKeys(sceneToJson(planet), "", keys);
    for (const char* key : {"planet.radius_km", "planet.sea_level", "planet.amplitude", "planet.wavelength_km", "planet.gain",
                            "planet.octaves", "planet.seed", "planet.ocean_colour", "planet.atmosphere_scale",
                            "planet.camera.altitude_km", "planet.camera.lat", "planet.camera.lon", "planet.camera.heading",
                            "planet.camera.pitch"})
        EXPECT_TRUE(keys.count(key)) << key;
}

TEST(DescriptionJson, EveryKeyIsDocumented) {
    const std::string docs = test::readFile(URBIS_EXAMPLES "/../scene_files.md");
    ASSERT_FALSE(docs.empty()) << "docs/scene_files.md";
    SceneDescription d;
    d.camera.geo = GeoCameraDescription{};
    d.planet = PlanetDescription{};
    std::set<std::string> keys;
    collectKeys(sceneToJson(d), "", keys);
    for (const std::string& key : keys) EXPECT_NE(docs.find("`" + key + "`"), std::string::npos) << key;
}

TEST(DescriptionJson, RoundTripKeepsEveryField) {
    const SceneDescription d = unusualScene();
    const ordered_json once = sceneToJson(d);
    const SceneDescription back = sceneFromJson(once, "scene.json");
    EXPECT_EQ(sceneToJson(back), once);
    EXPECT_EQ(back.camera.fov, 35.5f);
    EXPECT_EQ(back.source.metresPerLevel, 3.3f) << "floats read back bit for bit";
    EXPECT_EQ(back.materials.city.glassIor, 1.33f);
    EXPECT_EQ(back.geometry.modes.roofs, Representation::Plain);
    EXPECT_EQ(back.integrator.lightSampler, "uniform");
    EXPECT_EQ(back.astronomy.time, "2024-06-21T20:30+02:00");
    EXPECT_EQ((*back.astronomy.location)[1], 37.79);
    EXPECT_FALSE(back.astronomy.sunFromTime);
    EXPECT_EQ(back.film.layers, (std::vector<std::string>{"depth", "albedo"}));
    // Floats are written as their shortest decimal text.
    EXPECT_NE(sceneFileText(d).find("\"metres_per_level\": 3.3,"), std::string::npos) << sceneFileText(d);
    // Arrays of numbers and of names on one line each.
    EXPECT_NE(sceneFileText(d).find("\"layers\": [\"depth\", \"albedo\"]"), std::string::npos) << sceneFileText(d);
    EXPECT_NE(sceneFileText(d).find("\"irradiance\": [1.0, 2.0, 3.0]"), std::string::npos) << sceneFileText(d);
}

TEST(DescriptionJson, MissingKeysKeepTheirDefaults) {
    const SceneDescription d = sceneFromJson(ordered_json::parse(R"({"film": {"width": 300}})"), "scene.json");
    EXPECT_EQ(d.film.width, 300u);
    EXPECT_EQ(d.film.height, FilmDescription{}.height);
    EXPECT_EQ(sceneFromJson(ordered_json::parse("{}"), "s.json").integrator.spp, IntegratorDescription{}.spp);
}

TEST(DescriptionJson, ProblemsNameTheFileAndTheKeyPath) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"camera": {"fov": "wide"}})", "scene.json: camera.fov: expected a number"},
        {R"({"film": {"widht": 100}})", "scene.json: film.widht: unknown key"},
        {R"({"flim": {}})", "scene.json: flim: unknown key"},
        {R"({"film": {"width": 0}})", "scene.json: film.width: 0 is out of range 1..65536"},
        {R"({"film": {"width": 12.5}})", "scene.json: film.width: expected an integer"},
        {R"({"film": {"width": -4}})", "scene.json: film.width: -4 is out of range 1..65536"},
        {R"({"film": 3})", "scene.json: film: expected an object"},
        {R"({"integrator": {"spp": true}})", "scene.json: integrator.spp: expected an integer"},
        {R"({"integrator": {"kind": "bdpt"}})", "scene.json: integrator.kind: expected one of path"},
        {R"({"integrator": {"light_sampler": "tree"}})", "scene.json: integrator.light_sampler: expected one of uniform, power, bvh, colliders"},
        {R"({"sun": {"elevation": 91}})", "scene.json: sun.elevation: 91 is out of range -90..90"},
        {R"({"sky": {"zenith": [1, 2]}})", "scene.json: sky.zenith: expected an array of 3 numbers"},
        {R"({"sky": {"zenith": [1, -2, 3]}})", "scene.json: sky.zenith[1]: -2 is out of range 0..1000000"},
        {R"({"camera": {"position": [0, 1, 2], "target": null}})", "scene.json: camera.target: a camera position needs a target"},
        {R"({"camera": {"position": [0, 1, 2], "target": [0, 1, 2]}})", "scene.json: camera.target: position and target are the same point"},
        {R"({"camera": {"geo": {"lon": 10, "lat": 48, "roll": 3}}})", "scene.json: camera.geo.roll: unknown key"},
        {R"({"camera": {"geo": {"lon": 10, "lat": 48}}})", "scene.json: camera.geo: needs a city imported from source.osm"},
        {R"({"source": {"bbox": [10, 48, 9, 47], "osm": "a.osm"}})", "scene.json: source.bbox: need MINLON < MAXLON"},
        {R"({"source": {"bbox": [10, 48, 11, 49]}})", "scene.json: source.bbox: crops an OSM file and needs source.osm"},
        {R"({"source": {"height_range": [50, 10]}})", "scene.json: source.height_range: need MIN <= MAX"},
        {R"({"source": {"osm": 5}})", "scene.json: source.osm: expected a string"},
        {R"({"geometry": {"walls": "glass"}})", "scene.json: geometry.walls: expected one of procedural, triangles, plain"},
        {R"({"geometry": {"wall_tiles": "4y4"}})", "scene.json: geometry.wall_tiles: need 'whole' or SLOTSxFLOORS"},
        {R"({"materials": {"wall_colour_by_type": {"castle": [1, 1, 1]}}})",
         "scene.json: materials.wall_colour_by_type.castle: unknown building type"},
        {R"({"materials": {"ground": {"albedo": [0.1, 0.1, 2]}}})", "scene.json: materials.ground.albedo[2]: 2 is out of range 0..1"},
        {R"({"film": {"layers": ["albedo", "beauty"]}})", "scene.json: film.layers[1]: expected one of albedo, normal"},
        {R"({"film": {"layers": ["depth", "depth"]}})", "scene.json: film.layers[1]: named twice"},
        {R"({"film": {"layers": "depth"}})", "scene.json: film.layers: expected an array of names"},
        {"[1, 2]", "scene.json: expected a JSON object"},
    };
    for (const auto& [text, message] : cases) {
        const std::string problem = problemOf(text);
        EXPECT_EQ(problem.rfind(message, 0), 0u) << text << " -> " << problem;
        EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
    }
}

TEST(DescriptionJson, RelativeOsmPathsFollowTheSceneFile) {
    const fs::path dir = test::scratchDir("description_relative_osm");
    fs::create_directories(dir / "scenes");
    SceneDescription d;
    d.source.osm = (dir / "data" / "city.osm").string();
    writeSceneFile(d, (dir / "scenes" / "a.json").string());
    EXPECT_EQ(readSceneFile((dir / "scenes" / "a.json").string()).source.osm, d.source.osm);
    // A relative path in the file is relative to the file's folder.
    const std::string text = test::readFile(dir / "scenes" / "a.json");
    std::ofstream(dir / "scenes" / "b.json") << R"({"source": {"osm": "../data/city.osm"}})";
    EXPECT_EQ(fs::path(readSceneFile((dir / "scenes" / "b.json").string()).source.osm).lexically_normal(),
              (dir / "data" / "city.osm").lexically_normal());
    EXPECT_NE(text.find("\"osm\": \"" + d.source.osm + "\""), std::string::npos) << "absolute paths stay absolute";
}

TEST(DescriptionJson, MalformedAndMissingFilesNameTheFile) {
    const fs::path dir = test::scratchDir("description_malformed");
    std::ofstream(dir / "bad.json") << "{\n  \"film\": {\"width\": 10,}\n}\n";
    try {
        readSceneFile((dir / "bad.json").string());
        ADD_FAILURE() << "malformed JSON read";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind((dir / "bad.json").string() + ": malformed JSON at line 2, column ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    try {
        readSceneFile((dir / "none.json").string());
        ADD_FAILURE() << "missing file read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "none.json").string() + ": cannot open the scene file", 0), 0u) << e.what();
        EXPECT_EQ(e.kind(), FailureKind::BadInput);
    }
}

TEST(DescriptionJson, WallTileSizes) {
    EXPECT_EQ(wallTileSizeOf("whole")->slots, 0);
    EXPECT_EQ(wallTileSizeOf("4x3")->floors, 3);
    for (const char* bad : {"", "4", "4x", "x4", "0x4", "4x4x", "70000x1", "4y4", " 4x4"})
        EXPECT_FALSE(wallTileSizeOf(bad)) << bad;
}
