// The terrain: the record of the terrain kind (host+device POD), a heightfield of samples on a
// regular grid, bilinear between them, with a min/max hierarchy over its cells for the conservative
// march (geometry/terrain_intersect.h). Its samples and hierarchy live in SceneView::terrainData;
// fBm and DEM terrains both reach the renderer as samples (terrain/terrain_build.h).
#pragma once

#include "math/bounds.h"

#include <cstdint>

namespace urbis {

/// How rays find the terrain (--terrain-march).
enum class TerrainMarch : uint32_t {
    Hierarchy,   ///< min/max hierarchy, then the bilinear patch's quadratic: misses nothing
    Lei,         ///< the Cambridge work's step a + b distance + c height, then binary search
    Reference    ///< fixed small steps, then binary search: the accuracy bench's reference
};

/// The most hierarchy levels: grids up to 2^20 cells a side.
inline constexpr uint32_t kTerrainMaxLevels = 21;

/// Terrain materials, in order after TerrainRecord::material.
enum class TerrainMaterial : uint32_t { Rock, Grass, Snow, Sand, Count };

struct TerrainRecord {
    float x0 = 0, z0 = 0;       ///< world metres of sample (0, 0); sample (i, j) is at (x0 + i cell, z0 + j cell)
    float cell = 1;             ///< metres between samples
    uint32_t nx = 0, nz = 0;    ///< samples along x and z (at least 2 each); heights are terrainData[j nx + i]
    uint32_t levels = 0;        ///< hierarchy levels; level l's (min, max) pairs start at terrainData[levelStart[l]]
    uint32_t levelStart[kTerrainMaxLevels] = {};
    float yMin = 0, yMax = 0;   ///< of every sample, metres
    uint32_t material = 0;      ///< the first of the TerrainMaterial::Count materials
    TerrainMarch march = TerrainMarch::Hierarchy;
    /// The Cambridge rule's step a + b t + c (y - h): metres, per metre, per metre; and its bisections.
    float leiA = 0.05f, leiB = 0.002f, leiC = 0.4f;
    uint32_t leiBisections = 8;
    float referenceStep = 0.25f;  ///< metres, of the reference march
    /// Materials by height, slope and noise: sand below sandLevel, snow above snowLevel where the
    /// slope (1 - normal.y) is under rockSlope, rock where it is over, grass elsewhere; metres.
    float sandLevel = 2.0f, snowLevel = 1e9f, rockSlope = 0.35f;
    uint32_t seed = 7;          ///< of the material noise

    /// Cheap as a triangle per BVH leaf; hung from the root (attachLeavesAtRoot) as the ground is.
    static constexpr uint32_t kBvhCost = 1;
    static constexpr bool kBvhAtRoot = true;

    /// Cells along x and z.
    URBIS_HD uint32_t cellsX() const { return nx - 1; }
    URBIS_HD uint32_t cellsZ() const { return nz - 1; }
    /// Cells (or nodes) a side at hierarchy level l: level 0 is one node per cell, each level above
    /// halves both sides (rounding up) until one node is left.
    URBIS_HD uint32_t levelWidth(uint32_t l) const { return ((nx - 1) + (1u << l) - 1) >> l; }
    URBIS_HD uint32_t levelHeight(uint32_t l) const { return ((nz - 1) + (1u << l) - 1) >> l; }
};

/// World bounds of the terrain.
URBIS_HD inline Bounds3f primBounds(const TerrainRecord& t) {
    return {{t.x0, t.yMin, t.z0}, {t.x0 + t.cell * float(t.nx - 1), t.yMax, t.z0 + t.cell * float(t.nz - 1)}};
}

/// The terrain's height (metres) and its gradient (dh/dx, dh/dz) at world (x, z), bilinear between
/// the samples (`data`: SceneView::terrainData); outside the grid, the nearest edge's. For the water's
/// levels and beds, the city's lifting and the marches alike.
URBIS_HD inline float terrainHeight(const TerrainRecord& t, const float* data, float x, float z, Vec2f* gradient = nullptr) {
    float u = (x - t.x0) / t.cell, v = (z - t.z0) / t.cell;
    u = fminf(fmaxf(u, 0.0f), float(t.nx - 1));
    v = fminf(fmaxf(v, 0.0f), float(t.nz - 1));
    const uint32_t i = uint32_t(fminf(floorf(u), float(t.nx - 2))), j = uint32_t(fminf(floorf(v), float(t.nz - 2)));
    const float fu = u - float(i), fv = v - float(j);
    const float* row = data + size_t(j) * t.nx + i;
    const float h00 = row[0], h10 = row[1], h01 = row[t.nx], h11 = row[t.nx + 1];
    const float k1 = h10 - h00, k2 = h01 - h00, k4 = h00 - h10 - h01 + h11;
    if (gradient) *gradient = {(k1 + k4 * fv) / t.cell, (k2 + k4 * fu) / t.cell};
    return h00 + k1 * fu + k2 * fv + k4 * fu * fv;
}

} // namespace urbis
