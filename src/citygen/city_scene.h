// A meshed city as a scene: every array a CityMesh carries goes to Scene::build in one place, so no
// caller forgets the streets' road segments or lamps.
#pragma once

#include "citygen/city_mesher.h"
#include "scene/scene.h"

namespace urbis {

/// The scene of `mesh`: its triangles, walls (split into `tileSize` tiles), road segments, lamps and trees,
/// on the ground plane around `groundCentre` (world x, z), and the `terrain` where one is given
/// (the mesh placed on it first: citygen/city_on_terrain.h; its materials among the mesh's), which
/// replaces the plane over its grid (groundAround).
Scene buildCityScene(const CityMesh& mesh, WallTileSize tileSize = {}, Vec3f groundCentre = {},
                     const TerrainField& terrain = {});

/// `ground` less the rectangle of `grid` (x, z): four pieces around it. The terrain is the ground over
/// its grid, and the plane there would hide the water's beds carved below y = 0.
std::vector<GroundRecord> groundAround(const GroundRecord& ground, const Bounds3f& grid);

} // namespace urbis
