// A forest by domain repetition: the record of the forest kind (host+device POD). The plane is cut
// into square cells aligned with the world's axes; each cell holds at most one tree, whose presence,
// place in the cell, size and shape are a hash of the seed and the cell (the Cambridge work's
// domain repetition with jitter), grown into the same sphere-traced tree as a mapped one
// (scene/tree_growth.h). A ray walks the cells it crosses (geometry/forest_intersect.h), so a
// forest of millions of trees costs one record.
#pragma once

#include "math/bounds.h"
#include "scene/tree_growth.h"

#include <cstdint>

namespace urbis {

struct ForestRecord {
    /// World metres (x, z): a cell's tree belongs to this forest where its foot lies in
    /// [x0, x1) x [z0, z1). Cells of neighbouring forests of one seed and cell size join without a seam.
    float x0 = 0, z0 = 0, x1 = 0, z1 = 0;
    float cell = 6.0f;             ///< metres: cell (i, k) covers [i cell, (i + 1) cell) x [k cell, (k + 1) cell)
    float probability = 1.0f;      ///< that a cell holds a tree: density (trees per m^2) times cell^2, at most 1
    /// The ground's heights under the region (world metres): 0 and 0 on the flat ground; on the terrain
    /// (onTerrain) its samples' range, the feet standing on terrainHeight.
    float groundLo = 0, groundHi = 0;
    /// Of every tree the hash can grow (worked out on the host from the largest): metres its box reaches
    /// from its foot sideways and up; cells a tree's box may reach beyond its own (the ray's cell walk
    /// tests that many neighbours each side).
    float reach = 0, top = 0;
    int32_t neighbours = 1;
    float height = 10.0f;          ///< m, of an untagged tree before its variation
    float coniferShare = 0.3f;     ///< of the trees that are conifers
    TreeStyle style;
    uint32_t seed = 1;
    uint32_t object = 0;           ///< object id of every tree of the forest
    uint32_t material = 0;         ///< first of the trees' (bark, leaves) pairs (TreeLeaves)
    uint32_t onTerrain = 0;        ///< 1: the feet stand on the scene's terrain (its one TerrainRecord)
    uint32_t autumn = 0;           ///< 1: broadleaves in autumn colours

    /// A cell walk of many sphere traces: a leaf of its own, tested deferred on the GPU as trees are.
    static constexpr uint32_t kBvhCost = 64;
};

/// World bounds of every tree the forest can hold: its region grown by the trees' reach, from the
/// lowest ground to the highest ground plus the tallest tree, widened by a millimetre and a relative
/// margin for the rounding of world coordinates.
URBIS_HD inline Bounds3f primBounds(const ForestRecord& f) {
    const Vec3f lo{f.x0 - f.reach, f.groundLo, f.z0 - f.reach}, hi{f.x1 + f.reach, f.groundHi + f.top, f.z1 + f.reach};
    const float pad = 1e-3f + 1e-6f * maxComponent(vmax(vmax(hi, -hi), vmax(lo, -lo)));
    return {lo - Vec3f{pad, pad, pad}, hi + Vec3f{pad, pad, pad}};
}

} // namespace urbis
