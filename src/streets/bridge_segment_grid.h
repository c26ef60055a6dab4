// Segments of centerlines binned in a uniform grid in plan, to find the ways that pass under a deck
// (where it crosses them, where its piers may not stand) in time proportional to what is near.
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace urbis {

class SegmentGrid {
public:
    struct Segment {
        Vec2d a, b;
        double reach = 0;   ///< m around the segment that a query still finds it within
        uint32_t way = 0;   ///< the caller's way index
        uint32_t end = 0;   ///< index in the way's line of b (a is end - 1)
        int level = 0;      ///< the caller's level of the way
    };

    /// Adds the segments of `line` (each found by queries up to `reach` metres away). Segments longer
    /// than 10 km or beyond 10,000 km of the origin are left out: no city holds them.
    void add(const std::vector<Vec2d>& line, double reach, uint32_t way, int level);

    /// The segments in the grid cells that the box [lo, hi] (widened by their reach) touches, each
    /// once, in the order added.
    std::vector<const Segment*> near(Vec2d lo, Vec2d hi) const;

private:
    static int64_t cellOf(double coordinate);
    static uint64_t cellKey(int64_t cx, int64_t cy);
    std::vector<Segment> segments_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

} // namespace urbis
