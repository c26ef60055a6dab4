#include "bench_scene.h"

#include "citygen/city_mesher.h"
#include "layout/city_layout.h"
#include "osm/osm_import.h"

#include <cstdlib>
#include <filesystem>

namespace urbis::bench {

std::vector<Triangle> benchTriangles(std::string& description) {
    const char* env = std::getenv("URBIS_BENCH_OSM");
    std::string path = env ? env : URBIS_SHARED_DATA "/sf_downtown_2023.osm.pbf";
    CityModel city;
    if (std::filesystem::exists(path)) {
        city = importOsm(path, ImportOptions{});
        description = std::filesystem::path(path).filename().string();
    } else {
        LayoutParams params;
        params.buildings = 100000;
        city = generateCity(params);
        description = "generated city of 100000 buildings (" + path + " not found)";
    }
    // Plain walls: Embree traces stored triangles only, so both get the same mass model.
    CityMeshOptions options;
    options.geometry.walls = Representation::Plain;
    CityMesh mesh = meshCity(city, options);
    std::vector<Triangle> tris = std::move(mesh.mesh.triangles);
    // The renderer's ground is an analytic plane; Embree needs it as triangles, so both get a quad.
    Bounds3f b = mesh.cityBounds;
    Vec3f g[4] = {{b.lo.x, 0, b.lo.z}, {b.hi.x, 0, b.lo.z}, {b.hi.x, 0, b.hi.z}, {b.lo.x, 0, b.hi.z}};
    tris.push_back({g[0], g[1], g[2]});
    tris.push_back({g[0], g[2], g[3]});
    description += ", " + std::to_string(tris.size()) + " triangles";
    return tris;
}

} // namespace urbis::bench
