// A uniform grid of record indices by the cells their boxes touch: near-linear spatial
// queries over thousands of footprints (building parts, height neighbours).
#pragma once

#include "model/city_model.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace urbis {

class CellGrid {
public:
    /// A grid of square cells `cell` metres wide.
    explicit CellGrid(double cell) : cell_(cell) {}

    /// Files `index` under every cell that `box` {min, max} (metres) touches.
    void insert(uint32_t index, const std::array<Vec2d, 2>& box) {
        forCells(box, [&](uint64_t key) { cells_[key].push_back(index); });
    }

    /// Calls f(index) for each index filed under the cells that `box` touches, cell by cell
    /// in a fixed order (an index whose box spans cells may repeat).
    template <typename F>
    void query(const std::array<Vec2d, 2>& box, F&& f) const {
        forCells(box, [&](uint64_t key) {
            if (const auto it = cells_.find(key); it != cells_.end())
                for (uint32_t index : it->second) f(index);
        });
    }

private:
    template <typename F>
    void forCells(const std::array<Vec2d, 2>& box, F&& f) const {
        const auto cell = [this](double v) { return int64_t(std::floor(v / cell_)); };
        for (int64_t x = cell(box[0].x); x <= cell(box[1].x); ++x)
            for (int64_t y = cell(box[0].y); y <= cell(box[1].y); ++y)
                f(uint64_t(x) << 32 ^ uint64_t(uint32_t(y)));
    }

    double cell_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

} // namespace urbis
