#include "streets/bridge_segment_grid.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr double kCell = 32.0;  // m, a grid cell's side

bool cityScale(Vec2d a, Vec2d b) {
    return std::hypot(b.x - a.x, b.y - a.y) < 10000.0 && std::fabs(a.x) < 1e7 && std::fabs(a.y) < 1e7;
}

} // namespace

int64_t SegmentGrid::cellOf(double coordinate) { return int64_t(std::floor(coordinate / kCell)); }

uint64_t SegmentGrid::cellKey(int64_t cx, int64_t cy) { return (uint64_t(cx) << 32) ^ uint64_t(uint32_t(cy)); }

void SegmentGrid::add(const std::vector<Vec2d>& line, double reach, uint32_t way, int level) {
    for (size_t i = 1; i < line.size(); ++i) {
        const Vec2d a = line[i - 1], b = line[i];
        if (!cityScale(a, b) || !(reach >= 0 && reach < 1000)) continue;
        const uint32_t index = uint32_t(segments_.size());
        segments_.push_back({a, b, reach, way, uint32_t(i), level});
        for (int64_t cx = cellOf(std::min(a.x, b.x) - reach); cx <= cellOf(std::max(a.x, b.x) + reach); ++cx)
            for (int64_t cy = cellOf(std::min(a.y, b.y) - reach); cy <= cellOf(std::max(a.y, b.y) + reach); ++cy)
                cells_[cellKey(cx, cy)].push_back(index);
    }
}

std::vector<const SegmentGrid::Segment*> SegmentGrid::near(Vec2d lo, Vec2d hi) const {
    std::vector<uint32_t> found;
    if (!cityScale(lo, hi)) return {};
    for (int64_t cx = cellOf(lo.x); cx <= cellOf(hi.x); ++cx)
        for (int64_t cy = cellOf(lo.y); cy <= cellOf(hi.y); ++cy)
            if (const auto it = cells_.find(cellKey(cx, cy)); it != cells_.end())
                found.insert(found.end(), it->second.begin(), it->second.end());
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    std::vector<const Segment*> out;
    for (uint32_t index : found) out.push_back(&segments_[index]);
    return out;
}

} // namespace urbis
