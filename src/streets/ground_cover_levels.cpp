#include "streets/ground_cover_levels.h"

#include "model/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace urbis {

namespace {

/// Cells across the items' common box: a wide area (a landuse over the whole extract) is filed under
/// at most this squared, and small ones under one or a few.
constexpr double kCellsAcross = 128;

PlaneBox unionOf(const std::vector<PlaneBox>& boxes) {
    PlaneBox all = boxes.front();
    for (const PlaneBox& b : boxes) {
        all[0] = {std::min(all[0].x, b[0].x), std::min(all[0].y, b[0].y)};
        all[1] = {std::max(all[1].x, b[1].x), std::max(all[1].y, b[1].y)};
    }
    return all;
}

} // namespace

int planesBetween(float base, float ceiling, float step) {
    // The small margin keeps a plane that lands on the ceiling by rounding out of the band.
    return int(std::ceil((ceiling - base) / step - 1e-3f));
}

std::vector<int> stackPlanes(const std::vector<PlaneBox>& boxes, int planes,
                             const std::function<bool(size_t, size_t)>& overlap) {
    std::vector<int> plane(boxes.size(), -1);
    if (boxes.empty()) return plane;
    const PlaneBox all = unionOf(boxes);
    CellGrid placed(std::max(1.0, std::max(all[1].x - all[0].x, all[1].y - all[0].y) / kCellsAcross));
    std::vector<size_t> seenBy(boxes.size(), std::numeric_limits<size_t>::max());
    std::vector<uint32_t> near;
    for (size_t i = 0; i < boxes.size(); ++i) {
        near.clear();
        placed.query(boxes[i], [&](uint32_t j) {
            if (seenBy[j] != i && boxesOverlap(boxes[i], boxes[j])) near.push_back(j);
            seenBy[j] = i;
        });
        std::sort(near.begin(), near.end(),
                  [&](uint32_t a, uint32_t b) { return plane[a] != plane[b] ? plane[a] > plane[b] : a < b; });
        int level = 0;
        for (const uint32_t j : near)
            if (overlap(i, j)) {
                level = plane[j] + 1;
                break;
            }
        if (level >= planes) continue;
        plane[i] = level;
        placed.insert(uint32_t(i), boxes[i]);
    }
    return plane;
}

} // namespace urbis
