#include "streets/bridge_piers.h"

#include "model/polygon_ops.h"
#include "streets/bridge_deck.h"
#include "streets/polyline.h"
#include "streets/road_elevation.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr double kColumnHalf = 0.6;     // m, half a column's side
constexpr double kColumnsEvery = 10.0;  // m of deck width per column
constexpr double kShifts[] = {0.0, 4.0, -4.0, 8.0, -8.0};  // m along the deck, tried in order

/// A point `s` metres along `line` and the unit direction there; false past its end.
bool pointAlong(const std::vector<Vec2d>& line, const std::vector<float>& elevation, double s, Vec2d& p,
                Vec2d& direction, float& height) {
    if (s < 0) return false;
    for (size_t i = 1; i < line.size(); ++i) {
        const double dx = line[i].x - line[i - 1].x, dy = line[i].y - line[i - 1].y, length = std::hypot(dx, dy);
        if (s <= length && length > 0) {
            const double t = s / length;
            p = {line[i - 1].x + t * dx, line[i - 1].y + t * dy};
            direction = {dx / length, dy / length};
            height = float(elevation[i - 1] + t * (elevation[i] - elevation[i - 1]));
            return true;
        }
        s -= length;
    }
    return false;
}

/// The four sides of a square column at `c`, its sides along `d`, from the ground to `top`.
size_t addColumn(TriangleMesh& mesh, Vec2d c, Vec2d d, float top, TriangleInfo info) {
    const Vec2d n{-d.y, d.x};
    Vec2d corner[4];
    for (int k = 0; k < 4; ++k) {
        const double u = (k == 0 || k == 3) ? -kColumnHalf : kColumnHalf, v = k < 2 ? -kColumnHalf : kColumnHalf;
        corner[k] = {c.x + u * d.x + v * n.x, c.y + u * d.y + v * n.y};
    }
    for (int k = 0; k < 4; ++k) {
        const Vec2d a = corner[k], b = corner[(k + 1) % 4];
        mesh.add({worldFromStreet(a, 0.0), worldFromStreet(b, 0.0), worldFromStreet(b, top)}, info);
        mesh.add({worldFromStreet(a, 0.0), worldFromStreet(b, top), worldFromStreet(a, top)}, info);
    }
    return 8;
}

} // namespace

bool PierObstacles::blocks(Vec2d p, double radius, int level) const {
    for (const SegmentGrid::Segment* s : grid_.near(p, p))
        if (s->level < level && distanceToSegment(p, s->a, s->b) < s->reach - 1.0 + radius) return true;
    return false;
}

std::vector<double> chainOffsets(const std::vector<const std::vector<Vec2d>*>& lines) {
    std::unordered_map<PointKey, std::vector<size_t>, PointKeyHash> startingAt;
    std::unordered_map<PointKey, size_t, PointKeyHash> endingAt;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (lines[i]->size() < 2) continue;
        startingAt[keyOf(lines[i]->front())].push_back(i);
        ++endingAt[keyOf(lines[i]->back())];
    }
    std::vector<double> offsets(lines.size(), 0.0);
    std::vector<uint8_t> visited(lines.size(), 0);
    auto walk = [&](size_t head) {
        double offset = 0;
        for (size_t line = head;;) {
            visited[line] = 1;
            offsets[line] = offset;
            offset += polylineLength(*lines[line]);
            const auto next = startingAt.find(keyOf(lines[line]->back()));
            if (next == startingAt.end()) return;
            const auto unvisited = std::find_if(next->second.begin(), next->second.end(), [&](size_t n) { return !visited[n]; });
            if (unvisited == next->second.end()) return;
            line = *unvisited;
        }
    };
    for (size_t i = 0; i < lines.size(); ++i)
        if (lines[i]->size() >= 2 && !visited[i] && !endingAt.count(keyOf(lines[i]->front()))) walk(i);
    for (size_t i = 0; i < lines.size(); ++i)
        if (lines[i]->size() >= 2 && !visited[i]) walk(i);  // closed chains
    return offsets;
}

size_t meshPiers(const std::vector<Vec2d>& line, const std::vector<float>& elevation, const PierDeck& deck,
                 const PierObstacles& obstacles, TriangleInfo info, TriangleMesh& mesh) {
    if (line.size() < 2 || elevation.size() != line.size()) return 0;
    const double length = polylineLength(line), width = deck.leftWidth + deck.rightWidth;
    if (!(length > 0) || !(length < 1e6) || !(width > 0)) return 0;
    const int columns = std::max(1, int(std::lround(width / kColumnsEvery)));
    size_t n = 0;
    // The first station at or after the line's start: chain distances k * spacing + spacing / 2.
    const double first = std::ceil((deck.chainStart - kPierSpacing / 2) / kPierSpacing) * kPierSpacing + kPierSpacing / 2;
    for (double station = first - deck.chainStart; station < length; station += kPierSpacing) {
        for (double shift : kShifts) {
            Vec2d p, d;
            float e = 0;
            if (!pointAlong(line, elevation, station + shift, p, d, e)) continue;
            const float top = e + deck.underside;
            if (top < kPierMinClearance) continue;
            std::vector<Vec2d> centres;
            for (int c = 0; c < columns; ++c) {
                const double across = -deck.rightWidth + (c + 0.5) * width / columns;
                centres.push_back({p.x - d.y * across, p.y + d.x * across});
            }
            if (std::any_of(centres.begin(), centres.end(), [&](Vec2d q) { return obstacles.blocks(q, kColumnHalf * 1.5, deck.level); }))
                continue;
            for (Vec2d q : centres) n += addColumn(mesh, q, d, top, info);
            break;
        }
    }
    return n;
}

} // namespace urbis
