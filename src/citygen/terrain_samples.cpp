#include "citygen/terrain_samples.h"

#include <algorithm>
#include <iterator>

namespace urbis {

std::vector<float> terrainHeights(const TerrainField& terrain) {
    return {terrain.data.begin(), terrain.data.begin() + std::ptrdiff_t(terrain.record.nx) * terrain.record.nz};
}

void setTerrainHeights(TerrainField& terrain, std::vector<float> heights) {
    TerrainRecord& r = terrain.record;
    TerrainField rebuilt = TerrainField::fromSamples(r.x0, r.z0, r.cell, r.nx, r.nz, std::move(heights));
    // Only the extremes and the hierarchy's layout follow the heights.
    const TerrainRecord& built = rebuilt.record;
    std::copy(std::begin(built.levelStart), std::end(built.levelStart), std::begin(r.levelStart));
    r.levels = built.levels, r.yMin = built.yMin, r.yMax = built.yMax;
    terrain.data = std::move(rebuilt.data);
}

} // namespace urbis
