// A large export split into square tiles of the ground plane, one file each.
#pragma once

#include "export/export_scene.h"

#include <vector>

namespace urbis {

struct ExportTile {
    int x = 0, z = 0;        ///< the tile [x size, (x + 1) size) x [z size, (z + 1) size), world metres
    ExportScene scene;       ///< its nodes (materials renumbered to those it uses), the camera and sun, extras
};

/// `scene` cut into tiles of `size` metres (> 0), ordered by z then x, empty tiles left out. A building
/// goes whole to the tile of its bounds' centre; the other nodes are split triangle by triangle, by
/// centroid, keeping their names and extras. The tile's extras add its place and size.
std::vector<ExportTile> splitIntoTiles(const ExportScene& scene, float size);

} // namespace urbis
