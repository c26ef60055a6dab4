#include "osm/building_parts.h"

#include "model/polygon_ops.h"
#include "model/cell_grid.h"

#include <algorithm>

namespace urbis {

namespace {

constexpr double kCell = 64.0; // m, grid cell of the outline index

bool overlaps(const std::array<Vec2d, 2>& a, const std::array<Vec2d, 2>& b) {
    return a[0].x <= b[1].x && b[0].x <= a[1].x && a[0].y <= b[1].y && b[0].y <= a[1].y;
}

} // namespace

void replaceOutlinesByParts(std::vector<Building>& buildings, const GeosContext& geos,
                            ReasonLog& dropped) {
    if (std::none_of(buildings.begin(), buildings.end(), [](const Building& b) { return b.isPart; })) return;
    CellGrid grid(kCell);
    std::vector<std::array<Vec2d, 2>> boxes(buildings.size());
    for (uint32_t i = 0; i < buildings.size(); ++i) {
        boxes[i] = bounds(buildings[i].footprint.outer);
        if (!buildings[i].isPart) grid.insert(i, boxes[i]);
    }
    std::vector<char> replaced(buildings.size(), 0);
    for (uint32_t i = 0; i < buildings.size(); ++i) {
        if (!buildings[i].isPart) continue;
        const Polygon& part = buildings[i].footprint;
        const Vec2d c = centroid(part.outer);
        bool found = false;
        grid.query({c, c}, [&](uint32_t j) {
            if (contains(buildings[j].footprint, c)) replaced[j] = 1, found = true;
        });
        if (found) continue;
        const double partArea = area(part);
        grid.query(boxes[i], [&](uint32_t j) {
            if (!replaced[j] && overlaps(boxes[i], boxes[j]) &&
                geos.overlapArea(part, buildings[j].footprint) > 0.5 * partArea)
                replaced[j] = 1;
        });
    }
    size_t kept = 0;
    for (size_t i = 0; i < buildings.size(); ++i) {
        if (replaced[i]) {
            record(dropped, "replaced_by_parts", polygonRef(buildings[i].osmId));
            continue;
        }
        if (kept != i) buildings[kept] = std::move(buildings[i]);
        ++kept;
    }
    buildings.resize(kept);
}

} // namespace urbis
