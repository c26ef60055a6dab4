#include "citygen/city_scene.h"

namespace urbis {

std::vector<GroundRecord> groundAround(const GroundRecord& ground, const Bounds3f& grid) {
    GroundRecord west = ground, east = ground, north = ground, south = ground;
    west.x1 = grid.lo.x;
    east.x0 = grid.hi.x;
    north.x0 = south.x0 = grid.lo.x;
    north.x1 = south.x1 = grid.hi.x;
    north.z1 = grid.lo.z;
    south.z0 = grid.hi.z;
    return {west, east, north, south};
}

Scene buildCityScene(const CityMesh& mesh, WallTileSize tileSize, Vec3f groundCentre, const TerrainField& terrain) {
    const GroundRecord ground = GroundRecord::around(groundCentre.x, groundCentre.z, 0.0f, mesh.groundMaterial);
    const std::vector<GroundRecord> grounds =
        terrain.empty() ? std::vector{ground} : groundAround(ground, primBounds(terrain.record));
    Scene scene = Scene::build({.mesh = mesh.mesh, .materials = mesh.materials, .walls = mesh.walls,
                                .tileSize = tileSize, .grounds = grounds, .lamps = mesh.lamps, .trees = mesh.trees,
                                .terrain = terrain, .forests = mesh.forests});
    scene.roadSegments = mesh.roadSegments;
    return scene;
}

} // namespace urbis
