// The host-side scene: flat arrays in BVH leaf order, the BVH itself, lights, and what it all costs.
#pragma once

#include "accel/bvh_build.h"
#include "citygen/triangle_mesh.h"
#include "scene/scene_lights.h"
#include "scene/scene_view.h"

#include <vector>

namespace urbis {

/// Bytes the scene holds, by kind.
struct SceneMemory {
    size_t triangles = 0, triangleInfo = 0, walls = 0, primRefs = 0, materials = 0, bvh = 0;
    size_t total() const { return triangles + triangleInfo + walls + primRefs + materials + bvh; }
};

/// How walls are split into BVH primitives: tiles of at most this many slots x floors (0: no limit).
/// The default keeps whole walls: on the CPU, tiles measured slower (docs/facades.md).
struct WallTileSize {
    int slots = 0, floors = 0;
};

/// `walls` split into tiles of at most `size` cells (WallRecord::slot0): each tile a copy of its
/// wall's record with a sub-range of its grid; together they give the whole wall's hits, while each
/// has a box the size of its cells, so the BVH culls what one long, deep wall box would not.
/// A wall's slots (floors) are cut into equal runs as near to each other in length as they can be.
std::vector<WallRecord> splitWallsIntoTiles(const std::vector<WallRecord>& walls, WallTileSize size);

/// World bounds of a wall record's tile: its extent in u and v (WallRecord::tileU0 ...) and its
/// slab from w = -depthBack to w = depthFront; widened where it meets another tile of its wall.
Bounds3f wallTileBounds(const WallRecord& wall);

/// Every array here is mirrored to the device as it is: nodes, triangles, info, primRefs, walls, materials.
struct Scene {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;      ///< in the order the BVH leaves reach them
    std::vector<TriangleInfo> info;       ///< same order as triangles
    std::vector<uint32_t> primRefs;       ///< per leaf slot, a PrimRef; empty when there are only triangles
    std::vector<WallRecord> walls;        ///< wall tiles, in the order the BVH leaves reach them
    std::vector<Material> materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;
    SceneLights lights;                   ///< built from the rest by buildLights (lights/light_build.h)

    /// Builds one BVH over the triangles of `mesh` and the tiles of the procedural `walls`
    /// (splitWallsIntoTiles), and stores both in leaf order. Without walls every leaf slot is a
    /// triangle and primRefs stays empty.
    static Scene build(const TriangleMesh& mesh, std::vector<Material> materials,
                       const std::vector<WallRecord>& walls = {}, WallTileSize tileSize = {});
    SceneView view() const;
    SceneMemory memory() const;
};

} // namespace urbis
