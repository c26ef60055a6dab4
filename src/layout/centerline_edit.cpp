#include "layout/centerline_edit.h"

#include <cmath>

namespace urbis {

namespace {

double lengthOf(const std::vector<Vec2d>& line, size_t segment) {
    return std::hypot(line[segment + 1].x - line[segment].x, line[segment + 1].y - line[segment].y);
}

} // namespace

Spot advance(const std::vector<Vec2d>& line, Spot from, double metres) {
    Spot s = from;
    double left = s.offset + metres;  // from vertex s.segment
    while (left < 0 && s.segment > 0) left += lengthOf(line, --s.segment);
    while (left > lengthOf(line, s.segment) && s.segment + 2 < line.size()) left -= lengthOf(line, s.segment++);
    s.offset = std::fmax(0.0, std::fmin(left, lengthOf(line, s.segment)));
    return s;
}

CutCenterline cutAt(const std::vector<Vec2d>& line, const std::vector<Spot>& spots, double reuse) {
    CutCenterline out;
    size_t next = 0;  // the next spot to place
    for (size_t i = 0; i < line.size(); ++i) {
        out.points.push_back(line[i]);
        if (i + 1 == line.size()) break;
        const double len = lengthOf(line, i);
        for (; next < spots.size() && spots[next].segment == i; ++next) {
            const double s = spots[next].offset;
            if (s <= reuse) {
                out.vertexAt.push_back(out.points.size() - 1);  // vertex i
            } else if (len - s <= reuse) {
                out.vertexAt.push_back(out.points.size());  // vertex i + 1, pushed next
            } else {
                const double f = s / len;
                const Vec2d &a = line[i], &b = line[i + 1];
                const Vec2d p{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
                const Vec2d& last = out.points.back();
                if (std::hypot(p.x - last.x, p.y - last.y) > reuse) out.points.push_back(p);
                out.vertexAt.push_back(out.points.size() - 1);
            }
        }
    }
    return out;
}

} // namespace urbis
