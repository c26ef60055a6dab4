#include "streets/polyline.h"

#include <algorithm>
#include <cmath>

namespace urbis {

double polylineLength(const std::vector<Vec2d>& line) {
    double length = 0;
    for (size_t i = 1; i < line.size(); ++i) length += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    return length;
}

Vec2d leftNormal(Vec2d a, Vec2d b) {
    const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    if (!(length > 0.0)) return {0, 0};
    return {-dy / length, dx / length};
}

std::vector<Vec2d> offsetPolyline(const std::vector<Vec2d>& line, double distance, double mitreLimit) {
    std::vector<Vec2d> out(line.size());
    for (size_t i = 0; i < line.size(); ++i) {
        const Vec2d before = i > 0 ? leftNormal(line[i - 1], line[i]) : Vec2d{0, 0};
        const Vec2d after = i + 1 < line.size() ? leftNormal(line[i], line[i + 1]) : Vec2d{0, 0};
        Vec2d n = i == 0 ? after : i + 1 == line.size() ? before : Vec2d{before.x + after.x, before.y + after.y};
        const double nLength = std::hypot(n.x, n.y);
        if (!(nLength > 0.0)) n = before.x != 0 || before.y != 0 ? before : after;
        else n = {n.x / nLength, n.y / nLength};
        // The mitre's length along the bisector is distance / cos(half the turn), cos = n . segment normal.
        const double cosine = i == 0 || i + 1 == line.size() ? 1.0 : n.x * after.x + n.y * after.y;
        const double scale = std::min(1.0 / std::max(cosine, 1e-9), mitreLimit);
        out[i] = {line[i].x + n.x * distance * scale, line[i].y + n.y * distance * scale};
    }
    return out;
}

} // namespace urbis
