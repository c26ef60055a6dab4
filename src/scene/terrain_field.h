// The terrain on the host: its record and its samples with their min/max hierarchy, as the scene's
// terrain arrays hold them (scene/terrain_record.h), and the heights the city is lifted by.
#pragma once

#include "scene/terrain_record.h"

#include <vector>

namespace urbis {

struct TerrainField {
    TerrainRecord record;
    std::vector<float> data;   ///< the nx nz heights, then each hierarchy level's (min, max) pairs

    /// The field of `heights` (nx by nz, row j at [j nx]) with sample (0, 0) at world (x0, z0), `cell`
    /// metres apart: the record and the hierarchy over it. std::invalid_argument if fewer than 2x2.
    static TerrainField fromSamples(float x0, float z0, float cell, uint32_t nx, uint32_t nz, std::vector<float> heights);

    bool empty() const { return data.empty(); }
    /// The height (metres) at world (x, z): bilinear, the nearest edge's outside (terrainHeight).
    float heightAt(float x, float z) const { return terrainHeight(record, data.data(), x, z); }
    /// The lowest and highest ground (metres) over the rectangle [xa, xb] x [za, zb]: the extremes of
    /// the samples of every cell it touches, which bound the bilinear surface there.
    void rangeIn(float xa, float za, float xb, float zb, float& lo, float& hi) const;
};

} // namespace urbis
