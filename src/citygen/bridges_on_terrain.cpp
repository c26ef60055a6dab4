#include "citygen/bridges_on_terrain.h"

#include <algorithm>
#include <cmath>

namespace urbis {

BridgesOnTerrain::BridgesOnTerrain(const std::vector<BridgeSpan>& spans, const TerrainField& terrain) : terrain_(terrain) {
    for (const BridgeSpan& s : spans) {
        Span span{&s, {0.0}, 0, 0};
        for (size_t i = 1; i < s.line.size(); ++i)
            span.arc.push_back(span.arc.back() + std::hypot(s.line[i].x - s.line[i - 1].x, s.line[i].y - s.line[i - 1].y));
        span.deckStart = terrain.heightAt(float(s.line.front().x), float(s.line.front().y)) + s.elevation.front();
        span.deckEnd = terrain.heightAt(float(s.line.back().x), float(s.line.back().y)) + s.elevation.back();
        grid_.add(s.line, s.halfWidth, uint32_t(spans_.size()), 0);
        spans_.push_back(std::move(span));
    }
}

std::optional<float> BridgesOnTerrain::liftAt(float x, float z) const {
    const Vec2d p{x, z};
    double nearest = INFINITY;
    float lift = 0;
    for (const SegmentGrid::Segment* seg : grid_.near(p, p)) {
        const Span& s = spans_[seg->way];
        const size_t i = seg->end;  // the segment runs from point i - 1 to point i
        const double dx = seg->b.x - seg->a.x, dz = seg->b.y - seg->a.y, len2 = dx * dx + dz * dz;
        const double along = len2 > 0 ? ((p.x - seg->a.x) * dx + (p.y - seg->a.y) * dz) / len2 : 0.0;
        // Beyond the chain's ends lie its approaches, which follow the ground.
        if ((i == 1 && along < 0.0) || (i + 1 == s.arc.size() && along > 1.0)) continue;
        const double u = std::clamp(along, 0.0, 1.0);
        const double d = std::hypot(p.x - (seg->a.x + u * dx), p.y - (seg->a.y + u * dz));
        if (d > seg->reach || d >= nearest) continue;
        nearest = d;
        const double arc = s.arc[i - 1] + u * (s.arc[i] - s.arc[i - 1]);
        const double total = s.arc.back() > 0 ? s.arc.back() : 1.0;
        const float chord = s.deckStart + float(arc / total) * (s.deckEnd - s.deckStart);
        const float e = s.span->elevation[i - 1] + float(u) * (s.span->elevation[i] - s.span->elevation[i - 1]);
        lift = chord - e;
    }
    if (!(nearest < INFINITY)) return std::nullopt;
    return std::max(lift, terrain_.heightAt(x, z));
}

} // namespace urbis
