#include "scene/terrain_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace urbis {

TerrainField TerrainField::fromSamples(float x0, float z0, float cell, uint32_t nx, uint32_t nz, std::vector<float> heights) {
    if (nx < 2 || nz < 2 || heights.size() != size_t(nx) * nz || !(cell > 0.0f))
        throw std::invalid_argument("terrain: needs at least 2x2 samples a positive distance apart");
    TerrainField f;
    TerrainRecord& r = f.record;
    r.x0 = x0, r.z0 = z0, r.cell = cell, r.nx = nx, r.nz = nz;
    f.data = std::move(heights);
    const auto [lo, hi] = std::minmax_element(f.data.begin(), f.data.end());
    r.yMin = *lo, r.yMax = *hi;
    // Level 0: each cell's four samples, whose extremes bound the bilinear patch between them.
    r.levelStart[0] = uint32_t(f.data.size());
    for (uint32_t j = 0; j < r.cellsZ(); ++j)
        for (uint32_t i = 0; i < r.cellsX(); ++i) {
            const float* s = f.data.data() + size_t(j) * nx + i;
            const float a = s[0], b = s[1], c = s[nx], d = s[nx + 1];
            const float mn = std::min({a, b, c, d}), mx = std::max({a, b, c, d});
            f.data.push_back(mn);
            f.data.push_back(mx);
        }
    // Each level above: the extremes of up to 2x2 nodes below, until one node is left.
    uint32_t l = 0;
    while (r.levelWidth(l) > 1 || r.levelHeight(l) > 1) {
        if (l + 1 >= kTerrainMaxLevels) throw std::invalid_argument("terrain: grid too large");
        const uint32_t below = r.levelStart[l], w = r.levelWidth(l), h = r.levelHeight(l);
        r.levelStart[++l] = uint32_t(f.data.size());
        for (uint32_t j = 0; j < r.levelHeight(l); ++j)
            for (uint32_t i = 0; i < r.levelWidth(l); ++i) {
                float mn = INFINITY, mx = -INFINITY;
                for (uint32_t c = 0; c < 4; ++c) {
                    const uint32_t bi = 2 * i + (c & 1), bj = 2 * j + (c >> 1);
                    if (bi >= w || bj >= h) continue;
                    mn = std::min(mn, f.data[below + 2 * (size_t(bj) * w + bi)]);
                    mx = std::max(mx, f.data[below + 2 * (size_t(bj) * w + bi) + 1]);
                }
                f.data.push_back(mn);
                f.data.push_back(mx);
            }
    }
    if (f.data.size() >= (size_t(1) << 32)) throw std::invalid_argument("terrain: grid too large");
    r.levels = l + 1;
    return f;
}

void TerrainField::rangeIn(float xa, float za, float xb, float zb, float& lo, float& hi) const {
    const TerrainRecord& r = record;
    auto index = [&](float w, float origin, uint32_t cells) {
        return uint32_t(std::clamp(std::floor((w - origin) / r.cell), 0.0f, float(cells - 1)));
    };
    const uint32_t ia = index(xa, r.x0, r.cellsX()), ib = index(xb, r.x0, r.cellsX());
    const uint32_t ja = index(za, r.z0, r.cellsZ()), jb = index(zb, r.z0, r.cellsZ());
    lo = INFINITY, hi = -INFINITY;
    for (uint32_t j = ja; j <= jb + 1; ++j)
        for (uint32_t i = ia; i <= ib + 1; ++i) {
            const float h = data[size_t(j) * r.nx + i];
            lo = std::min(lo, h);
            hi = std::max(hi, h);
        }
}

} // namespace urbis
