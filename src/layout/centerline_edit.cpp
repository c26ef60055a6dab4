#include "layout/centerline_edit.h"

#include <cmath>

namespace urbis {

std::vector<double> distancesAlong(const std::vector<Vec2d>& line) {
    std::vector<double> out(line.size(), 0.0);
    for (size_t i = 1; i < line.size(); ++i)
        out[i] = out[i - 1] + std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    return out;
}

CutCenterline cutAt(const std::vector<Vec2d>& line, const std::vector<double>& distances, double reuse) {
    CutCenterline out;
    const std::vector<double> along = distancesAlong(line);
    size_t next = 0;  // the next distance to place
    for (size_t i = 0; i < line.size(); ++i) {
        // Distances before vertex i: on the segment from i - 1, or served by a vertex close by.
        for (; next < distances.size() && distances[next] <= along[i] + reuse; ++next) {
            const double s = distances[next];
            if (!out.points.empty() && s - along[i - 1] <= reuse) {
                out.vertexAt.push_back(out.points.size() - 1);
            } else if (along[i] - s <= reuse) {
                out.vertexAt.push_back(out.points.size());  // vertex i, pushed below
            } else {
                const double f = (s - along[i - 1]) / (along[i] - along[i - 1]);
                const Vec2d &a = line[i - 1], &b = line[i];
                out.vertexAt.push_back(out.points.size());
                out.points.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
            }
        }
        out.points.push_back(line[i]);
    }
    for (; next < distances.size(); ++next) out.vertexAt.push_back(out.points.size() - 1);  // past the end
    return out;
}

} // namespace urbis
