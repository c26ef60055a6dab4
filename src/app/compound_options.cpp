#include "app/compound_options.h"

#include "app/option_parsing.h"
#include "astro/civil_time.h"
#include "base/input_error.h"
#include "description/scene_checks.h"
#include "layout/city_layout.h"

#include <cstdio>

namespace urbis {

namespace {

Vec3f vec3Of(const std::vector<double>& v, size_t first) {
    return Vec3f{float(v[first]), float(v[first + 1]), float(v[first + 2])};
}

void applyHeightRange(SceneDescription& d, const std::string& text) {
    std::vector<double> r = parseNumberList("--building-height-range", text, ':', 2, 2);
    if (!(r[0] >= 0.0 && r[0] <= r[1] && r[1] <= 1000.0))
        throw InputError("--building-height-range: need 0 <= MIN <= MAX <= 1000 metres, got '" + text + "'",
                         FailureKind::Usage);
    d.source.heightRange = std::array<float, 2>{float(r[0]), float(r[1])};
}

void applyCamera(SceneDescription& d, const std::string& text) {
    std::vector<double> c = parseNumberList("--camera", text, ',', 6, 6);
    d.camera.position = vec3Of(c, 0);
    d.camera.target = vec3Of(c, 3);
    d.camera.geo.reset();
}

void applyCameraGeo(SceneDescription& d, const std::string& text) {
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
}

void applyTime(SceneDescription& d, const std::string& text) {
    std::string error;
    if (!parseIsoTime(text, error)) throw InputError("--time: '" + text + "': " + error, FailureKind::Usage);
    d.astronomy.time = text;
    d.astronomy.sunFromTime = true;
}

void applySun(SceneDescription& d, const std::string& text) {
    std::vector<double> s = parseNumberList("--sun", text, ',', 2, 2);
    if (!(s[0] >= -90.0 && s[0] <= 90.0)) throw InputError("--sun: elevation must be in [-90, 90] degrees", FailureKind::Usage);
    if (!(s[1] >= -360.0 && s[1] <= 360.0))
        throw InputError("--sun: azimuth must be in [-360, 360] degrees", FailureKind::Usage);
    d.sun.elevation = float(s[0]);
    d.sun.azimuth = float(s[1]);
    d.astronomy.sunFromTime = false;
}

void applyWallTiles(SceneDescription& d, const std::string& text) {
    if (!wallTileSizeOf(text))
        throw InputError("--wall-tiles: need 'whole' or SLOTSxFLOORS (e.g. 4x4), got '" + text + "'", FailureKind::Usage);
    d.geometry.wallTiles = text;
}

void applyPlanet(SceneDescription& d, const std::string& text) {
    if (!d.planet) d.planet = PlanetDescription{};
    if (text.empty()) return;
    const double r = parseNumberList("--planet", text, ',', 1, 1)[0];
    if (!(r >= 10.0 && r <= 1e6))
        throw InputError("--planet: radius must be in [10, 1e6] km, got '" + text + "'", FailureKind::Usage);
    d.planet->radiusKm = r;
}

void applyCameraOrbit(SceneDescription& d, const std::string& text) {
    if (!d.planet) throw InputError("--camera-orbit: places the camera above a planet and needs --planet", FailureKind::Usage);
    const std::vector<double> c = parseNumberList("--camera-orbit", text, ',', 3, 5);
    if (!(c[0] >= 0.0 && c[0] <= 1e6 && c[1] >= -90.0 && c[1] <= 90.0 && c[2] >= -360.0 && c[2] <= 360.0))
        throw InputError("--camera-orbit: need 0 <= ALT_KM <= 1e6, LAT in [-90, 90], LON in [-360, 360], got '" + text + "'",
                         FailureKind::Usage);
    PlanetCameraDescription& camera = d.planet->camera;
    camera = {c[0], c[1], c[2], c.size() > 3 ? float(c[3]) : 0.0f, c.size() > 4 ? float(c[4]) : -90.0f};
    if (!(camera.pitch >= -90.0f && camera.pitch <= 90.0f))
        throw InputError("--camera-orbit: PITCH must be in [-90, 90] degrees", FailureKind::Usage);
}

std::vector<CompoundOption> makeCompoundOptions() {
    const SceneDescription d;
    const LayoutParams layout;
    char place[48];
    std::snprintf(place, sizeof place, "%.4f,%.4f", kDefaultLocation[0], kDefaultLocation[1]);
    return {
        {"--bbox", "Crop OSM to MINLON,MINLAT,MAXLON,MAXLAT (default: the file's header box)",
         [](SceneDescription& s, const std::string& text) { s.source.bbox = parseBbox(text); }},
        {"--building-height-range",
         "MIN:MAX metres, seeded uniform, for OSM buildings without height or levels tags (without it their heights are "
         "estimated from tagged neighbours of their type and a table of types) and for the generated city (default " +
             std::to_string(int(layout.minBuildingHeight)) + ":" + std::to_string(int(layout.maxBuildingHeight)) + ")",
         applyHeightRange},
        {"--camera", "X,Y,Z,TX,TY,TZ: position and target in world metres (x east, y up, z south)", applyCamera},
        {"--camera-geo",
         "LON,LAT,ALTITUDE,HEADING,PITCH (OSM only; degrees, metres above y = 0, sea level on a DEM; ALTITUDE with the "
         "suffix agl, as 50agl: metres above the terrain under the camera)",
         applyCameraGeo},
        {"--time", "ISO 8601 date and time with a UTC offset or Z (2024-06-21T20:30+02:00): sets the sun, the moon and the stars",
         applyTime},
        {"--location",
         std::string("LON,LAT in degrees the sky is seen from (default: the OSM extract's centre; the generated city: "
                     "Prague, ") + place + ")",
         [](SceneDescription& s, const std::string& text) { s.astronomy.location = parseLocation("--location", text); }},
        {"--sun", "ELEVATION,AZIMUTH of the sun in degrees (azimuth clockwise from north)", applySun,
         std::to_string(int(d.sun.elevation)) + "," + std::to_string(int(d.sun.azimuth))},
        {"--geometry",
         "procedural|triangles|plain for every kind, or KIND=MODE,... (kinds: walls, roofs, lamps, trees, buildings); "
         "plain: no facades",
         [](SceneDescription& s, const std::string& text) { s.geometry.modes = parseGeometryModes(text); }, "procedural"},
        {"--wall-tiles", "whole, or SLOTSxFLOORS: split each procedural wall into BVH tiles of at most that many cells",
         applyWallTiles, d.geometry.wallTiles},
        {"--planet",
         "[RADIUS_KM]: render a whole planet instead of the city (default Earth-like, 6360 km, or the scene file's planet)",
         applyPlanet, "", true},
        {"--camera-orbit",
         "ALT_KM,LAT,LON[,HEADING,PITCH]: the camera above a planet (--planet): km above the ground under it, degrees "
         "(heading clockwise from north, pitch above the horizon; default 0,-90: straight down)",
         applyCameraOrbit},
    };
}

} // namespace

const std::vector<CompoundOption>& compoundOptions() {
    static const std::vector<CompoundOption> options = makeCompoundOptions();
    return options;
}

const CompoundOption* compoundOptionNamed(std::string_view flag) {
    for (const CompoundOption& option : compoundOptions())
        if (flag == option.flag) return &option;
    return nullptr;
}

} // namespace urbis
