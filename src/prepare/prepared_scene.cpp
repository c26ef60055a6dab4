#include "prepare/prepared_scene.h"

#include "base/step_timer.h"
#include "base/input_error.h"
#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "citygen/city_terrain.h"
#include "description/scene_checks.h"
#include "description/scene_parts.h"
#include "media/cloud_build.h"
#include "prepare/camera_checks.h"
#include "prepare/planet_scene.h"
#include "prepare/scene_city.h"
#include "prepare/scene_lighting.h"

#include <cstdio>

namespace urbis {

namespace {

/// Says on stderr what is wrong with the camera, or when `strict` fails on the first problem.
void checkCamera(bool strict, const Camera& camera, const CityModel& city, const Bounds3f& cityBounds) {
    for (const std::string& problem : cameraProblems(camera, city, cityBounds)) {
        if (strict) throw InputError(problem + " (--strict)", FailureKind::Usage);
        std::fprintf(stderr, "urbis: warning: %s\n", problem.c_str());
    }
}

nlohmann::json countsJson(const CityModel& city) {
    double heights = 0;
    for (const Building& b : city.buildings) heights += b.height;
    return {{"buildings", city.buildings.size()},
            {"mean_building_height", city.buildings.empty() ? 0.0 : heights / double(city.buildings.size())}, {"building_parts", city.buildingParts()},
            {"roads", city.roads.size()}, {"lamps", city.lamps.size()}, {"trees", city.trees.size()},
            {"areas", city.areas.size()}};
}

/// What the stats keep of the city and its mesh.
BuildSummary summarise(const CityModel& city, const CityMesh& mesh) {
    BuildSummary s;
    s.source = city.source;
    s.buildings = city.buildings.size();
    s.counts = countsJson(city);
    for (const auto& [kind, n] : mesh.streetCounts) s.counts[kind] = n;
    // Import and meshing use their own reasons (docs/cli.md); the meshed roofs' fallbacks count as repairs.
    s.dropped = mesh.dropped;
    s.repaired = nlohmann::json::object();
    for (const auto& [reason, entry] : city.dropped) s.dropped[reason] = s.dropped.value(reason, uint64_t(0)) + entry.count;
    for (const auto& [reason, entry] : city.repaired) s.repaired[reason] = entry.count;
    for (const auto& [reason, n] : mesh.roofFallbacks) s.repaired["roof_" + reason] = n;
    if (mesh.holesDropped) s.repaired["footprint_hole_dropped"] = mesh.holesDropped;
    s.trianglesByKind = mesh.trianglesByKind;
    s.facadeWalls = mesh.facadeWalls;
    s.facadeCells = mesh.facadeCells;
    return s;
}

} // namespace

PreparedScene prepareScene(const SceneDescription& d, bool strict, size_t memoryLimit) {
    if (d.planet) return preparePlanetScene(d);
    PreparedScene p;
    const CityMeshOptions meshOptions = cityMeshOptionsOf(d, memoryLimit);
    p.geometry = meshOptions.geometry;
    CityMesh mesh;
    TerrainField terrain;
    {
        auto t0 = SteadyClock::now();
        CityModel city = loadSceneCity(d);
        p.secondsImport = secondsSince(t0);

        t0 = SteadyClock::now();
        mesh = meshCity(city, meshOptions);
        terrain = cityTerrainOf(d.terrain, city.origin, mesh, d.water);
        p.secondsCitygen = secondsSince(t0);

        p.camera = cameraOf(d.camera, float(d.film.width) / float(d.film.height), city.origin, mesh.framingPieces,
                            groundOf(terrain));
        checkCamera(strict, p.camera, city, mesh.cityBounds);
        p.origin = city.origin;
        p.windowUses.reserve(city.buildings.size());
        for (const Building& b : city.buildings) p.windowUses.push_back(windowUseOf(b.type));
        p.summary = summarise(city, mesh);
    }  // the city is released here, before the scene's copy of the mesh is made

    auto t0 = SteadyClock::now();
    const Vec3f centre = mesh.cityBounds.empty() ? Vec3f{} : mesh.cityBounds.centre();
    p.scene = buildCityScene(mesh, *wallTileSizeOf(d.geometry.wallTiles), centre, terrain);
    buildClouds(p.scene, cloudLayerOf(d.clouds));
    lightScene(p.scene, d, p.origin);
    p.secondsBvh = secondsSince(t0);
    p.framingPieces = std::move(mesh.framingPieces);
    return p;  // and the mesh here: the scene holds every triangle in its own order
}

} // namespace urbis
