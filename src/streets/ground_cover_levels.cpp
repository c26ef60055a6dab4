#include "streets/ground_cover_levels.h"

#include <cmath>

namespace urbis {

int planesBetween(float base, float ceiling, float step) {
    // The small margin keeps a plane that lands on the ceiling by rounding out of the band.
    return int(std::ceil((ceiling - base) / step - 1e-3f));
}

std::vector<int> stackPlanes(size_t items, int planes, const std::function<bool(size_t, size_t)>& overlap) {
    std::vector<int> plane(items, -1);
    std::vector<std::vector<size_t>> onPlane(size_t(planes > 0 ? planes : 0));
    for (size_t i = 0; i < items; ++i) {
        int level = 0;
        for (int p = planes - 1; p >= 0 && level == 0; --p)
            for (const size_t j : onPlane[size_t(p)])
                if (overlap(i, j)) {
                    level = p + 1;
                    break;
                }
        if (level >= planes) continue;
        plane[i] = level;
        onPlane[size_t(level)].push_back(i);
    }
    return plane;
}

} // namespace urbis
