#include "layout/street_furniture.h"

#include "math/hash.h"

#include <cmath>

namespace urbis {

std::vector<Vec2d> pointsBeside(const Road& road, double spacing, double offset) {
    std::vector<Vec2d> out;
    double next = 0.5 * spacing;  // distance along the road of the next point
    double start = 0;             // distance along the road where the current segment starts
    for (size_t i = 0; i + 1 < road.centerline.size(); ++i) {
        Vec2d a = road.centerline[i], b = road.centerline[i + 1];
        double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
        if (len <= 0) continue;
        Vec2d left{-dy / len * offset, dx / len * offset};
        for (; next <= start + len; next += spacing) {
            double f = (next - start) / len;
            Vec2d p{a.x + f * dx, a.y + f * dy};
            out.push_back({p.x + left.x, p.y + left.y});
            out.push_back({p.x - left.x, p.y - left.y});
        }
        start += len;
    }
    return out;
}

void plantPark(const Rect2d& park, double areaPerTree, uint32_t key, std::vector<Tree>& out) {
    constexpr double kEdge = 2.0;
    const double w = park.width() - 2 * kEdge, h = park.height() - 2 * kEdge;
    if (w <= 0 || h <= 0) return;
    HashStream rng{key};
    const auto count = static_cast<int>(w * h / areaPerTree);
    for (int i = 0; i < count; ++i) {
        Tree t;
        t.position = {park.x0 + kEdge + w * rng.uniform(), park.y0 + kEdge + h * rng.uniform()};
        t.height = rng.uniform(6.0f, 14.0f);
        t.crownDiameter = rng.uniform(4.0f, 8.0f);
        out.push_back(t);
    }
}

} // namespace urbis
