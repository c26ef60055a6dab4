#include "citygen/city_scene.h"

namespace urbis {

Scene buildCityScene(const CityMesh& mesh, WallTileSize tileSize, Vec3f groundCentre, const TerrainField& terrain) {
    Scene scene = Scene::build(mesh.mesh, mesh.materials, mesh.walls, tileSize,
                               {GroundRecord::around(groundCentre.x, groundCentre.z, 0.0f, mesh.groundMaterial)}, mesh.lamps,
                               mesh.trees, terrain);
    scene.roadSegments = mesh.roadSegments;
    return scene;
}

} // namespace urbis
