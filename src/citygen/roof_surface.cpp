#include "citygen/roof_surface.h"

#include "citygen/building_mesher.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace urbis {

double RoofProfile::at(double x) const {
    if (x <= s.front()) return h.front();
    if (x >= s.back()) return h.back();
    const size_t i = size_t(std::upper_bound(s.begin(), s.end(), x) - s.begin()) - 1;
    const double t = (x - s[i]) / (s[i + 1] - s[i]);
    const double height = h[i] + t * (h[i + 1] - h[i]);
    // Within a tenth of a millimetre of the wall top is on it: in single precision the point
    // could land on the wall top's own vertex and fold a gable triangle onto an edge.
    return std::abs(height) < 1e-4 ? 0.0 : height;
}

Vec3f RoofSink::at(Vec2d p, double h) const { return worldFromCity(p, base + h); }

void RoofSink::roof(Vec3f a, Vec3f b, Vec3f c) {
    mesh.add({a, b, c}, roofInfo);
    ++roofTriangles;
}

void RoofSink::wall(Vec3f a, Vec3f b, Vec3f c) {
    mesh.add({a, b, c}, wallInfo);
    ++wallTriangles;
}

void appendCutEdge(LevelPoint a, LevelPoint b, const std::vector<double>& cuts, std::vector<LevelPoint>& out) {
    out.push_back(a);
    const double lo = std::min(a.s, b.s), hi = std::max(a.s, b.s);
    auto first = std::upper_bound(cuts.begin(), cuts.end(), lo);
    auto last = std::lower_bound(cuts.begin(), cuts.end(), hi);
    if (first >= last) return;
    // Interpolate from the lexicographically smaller endpoint, whichever way the edge is walked.
    const bool swapped = std::tie(b.p.x, b.p.y) < std::tie(a.p.x, a.p.y);
    const LevelPoint from = swapped ? b : a, to = swapped ? a : b;
    std::vector<LevelPoint> crossings;
    for (auto c = first; c != last; ++c) {
        const double t = (*c - from.s) / (to.s - from.s);
        crossings.push_back({{from.p.x + t * (to.p.x - from.p.x), from.p.y + t * (to.p.y - from.p.y)}, *c});
    }
    // Crossings are sorted by s; walk them from a's side.
    if (a.s > b.s) std::reverse(crossings.begin(), crossings.end());
    out.insert(out.end(), crossings.begin(), crossings.end());
}

void forEachSlab(const std::array<LevelPoint, 3>& triangle, const std::vector<double>& cuts,
                 const std::function<void(const std::vector<LevelPoint>&, size_t)>& piece) {
    std::vector<LevelPoint> boundary;
    for (size_t i = 0; i < 3; ++i) appendCutEdge(triangle[i], triangle[(i + 1) % 3], cuts, boundary);
    const double lowest = std::min({triangle[0].s, triangle[1].s, triangle[2].s});
    const double highest = std::max({triangle[0].s, triangle[1].s, triangle[2].s});
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<LevelPoint> part;
    for (size_t slab = 0; slab <= cuts.size(); ++slab) {
        const double lo = slab == 0 ? -inf : cuts[slab - 1], hi = slab == cuts.size() ? inf : cuts[slab];
        if (hi < lowest || lo > highest) continue;
        part.clear();
        for (const LevelPoint& q : boundary)
            if (q.s >= lo && q.s <= hi) part.push_back(q);
        if (part.size() >= 3) piece(part, slab);
    }
}

void emitProfiledTriangle(const std::array<LevelPoint, 3>& triangle, const RoofProfile& profile, RoofSink& sink) {
    forEachSlab(triangle, profile.cuts(), [&](const std::vector<LevelPoint>& part, size_t) {
        const Vec3f apex = sink.at(part[0].p, profile.at(part[0].s));
        for (size_t i = 1; i + 1 < part.size(); ++i)
            sink.roof(apex, sink.at(part[i].p, profile.at(part[i].s)), sink.at(part[i + 1].p, profile.at(part[i + 1].s)));
    });
}

void emitWallUnderRoof(LevelPoint a, LevelPoint b, const RoofProfile& profile, RoofSink& sink) {
    std::vector<LevelPoint> top;
    appendCutEdge(a, b, profile.cuts(), top);
    top.push_back(b);
    // The region under a concave height is convex: a fan from the bottom corner at a covers it.
    const Vec3f corner = sink.at(a.p, 0.0);
    for (size_t i = 0; i + 1 < top.size(); ++i) {
        const double h0 = profile.at(top[i].s);
        if (i == 0 && h0 == 0.0) continue;
        sink.wall(corner, sink.at(top[i].p, h0), sink.at(top[i + 1].p, profile.at(top[i + 1].s)));
    }
    if (profile.at(b.s) != 0.0) sink.wall(corner, sink.at(b.p, profile.at(b.s)), sink.at(b.p, 0.0));
}

} // namespace urbis
