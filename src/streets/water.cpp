#include "streets/water.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace urbis {

std::vector<bool> separateWaters(CoverShapes& shapes, const std::vector<size_t>& water, const std::vector<bool>& ribbon) {
    std::vector<double> area(water.size());
    for (size_t i = 0; i < water.size(); ++i) area[i] = shapes.area(water[i]);
    std::vector<size_t> smallestFirst(water.size());
    std::iota(smallestFirst.begin(), smallestFirst.end(), size_t(0));
    std::stable_sort(smallestFirst.begin(), smallestFirst.end(),
                     [&](size_t a, size_t b) { return std::pair(ribbon[a], area[a]) < std::pair(ribbon[b], area[b]); });
    std::vector<bool> left(water.size(), true);
    for (size_t i = 0; i < smallestFirst.size(); ++i) {
        const size_t shape = water[smallestFirst[i]];
        for (size_t j = 0; j < i && left[smallestFirst[i]]; ++j) {
            const size_t cut = water[smallestFirst[j]];
            if (left[smallestFirst[j]] && shapes.overlap(shape, cut)) left[smallestFirst[i]] = shapes.subtract(shape, cut);
        }
    }
    return left;
}

} // namespace urbis
