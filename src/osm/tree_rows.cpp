#include "osm/tree_rows.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace urbis {

std::vector<LonLat> treeRowPoints(const GeoLine& line, double spacing) {
    std::vector<LonLat> points;
    if (line.empty() || !(spacing > 0)) return points;
    constexpr double kMetresPerDegree = 6371000.0 * std::numbers::pi / 180.0;
    points.push_back(line.front());
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const LonLat a = line[i], b = line[i + 1];
        const double east = (b.lon - a.lon) * kMetresPerDegree * std::cos(a.lat * std::numbers::pi / 180.0);
        const double north = (b.lat - a.lat) * kMetresPerDegree;
        const int pieces = std::max(1, int(std::ceil(std::hypot(east, north) / spacing)));
        for (int k = 1; k <= pieces; ++k) {
            const double f = double(k) / pieces;
            points.push_back({a.lon + (b.lon - a.lon) * f, a.lat + (b.lat - a.lat) * f});
        }
    }
    return points;
}

} // namespace urbis
