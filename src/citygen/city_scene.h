// A meshed city as a scene: every array a CityMesh carries goes to Scene::build in one place, so no
// caller forgets the streets' road segments or lamps.
#pragma once

#include "citygen/city_mesher.h"
#include "scene/scene.h"

namespace urbis {

/// The scene of `mesh`: its triangles, walls (split into `tileSize` tiles), road segments, lamps and trees,
/// on the ground plane around `groundCentre` (world x, z), and the `terrain` where one is given
/// (the mesh placed on it first: citygen/city_on_terrain.h; its materials among the mesh's).
Scene buildCityScene(const CityMesh& mesh, WallTileSize tileSize = {}, Vec3f groundCentre = {},
                     const TerrainField& terrain = {});

} // namespace urbis
