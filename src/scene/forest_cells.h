// Which tree a cell of a forest holds (host+device): the domain repetition's rule, a hash of the
// forest's seed and the cell, shared by the ray's cell walk (geometry/forest_intersect.h), the
// shading of its hits and the host's count of the trees (nature/forest_records.h).
#pragma once

#include "scene/forest_record.h"
#include "scene/terrain_record.h"

#include <cstdint>

namespace urbis {

/// What a forest's trees stand on: the scene's terrain (its record and SceneView::terrainData) or,
/// without one, the flat ground at the forest's groundLo.
struct ForestGround {
    const TerrainRecord* terrain = nullptr;
    const float* terrainData = nullptr;
};

/// Whether cell (i, k) of `forest` holds a tree whose foot lies in the forest's region: then the
/// foot's world (x, z), and `rng` (the cell's stream) left where the tree's growth draws on.
URBIS_HD inline bool forestFoot(const ForestRecord& f, int32_t i, int32_t k, HashStream& rng, float& x, float& z) {
    rng = HashStream{hash3(f.seed, uint32_t(i), uint32_t(k))};
    if (!(rng.uniform() < f.probability)) return false;
    x = exactMul(exactAdd(float(i), rng.uniform()), f.cell);
    z = exactMul(exactAdd(float(k), rng.uniform()), f.cell);
    return x >= f.x0 && x < f.x1 && z >= f.z0 && z < f.z1;
}

/// The tree of cell (i, k) of `forest` if the cell holds one (forestFoot): then its record, its foot
/// on `ground`. Everything is a hash of the seed and the cell: whether it holds a tree, where in the
/// cell, its size, shape and shade (grownTreeRecord).
URBIS_HD inline bool forestTreeAt(const ForestRecord& f, const ForestGround& ground, int32_t i, int32_t k, TreeRecord& tree) {
    HashStream rng;
    float x, z;
    if (!forestFoot(f, i, k, rng, x, z)) return false;
    TreeSizes sizes;
    sizes.height = f.height;
    sizes.conifer = rng.uniform() < f.coniferShare;
    sizes.autumn = f.autumn != 0;
    const float y = ground.terrain ? terrainHeight(*ground.terrain, ground.terrainData, x, z) : f.groundLo;
    tree = grownTreeRecord({x, y, z}, sizes, f.style, rng, f.object, f.material);
    return true;
}

} // namespace urbis
