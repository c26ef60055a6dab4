#include "citygen/ear_clipping.h"

namespace urbis {

namespace {

double cross(Vec2d o, Vec2d a, Vec2d b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool same(Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; }

/// Whether p lies inside or on the counter-clockwise triangle abc.
bool inTriangle(Vec2d p, Vec2d a, Vec2d b, Vec2d c) {
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

} // namespace

std::vector<std::array<uint32_t, 3>> earClip(const std::vector<Vec2d>& ring) {
    std::vector<std::array<uint32_t, 3>> out;
    if (ring.size() < 3) return out;
    double area = 0;
    for (size_t i = 0; i < ring.size(); ++i) area += cross({0, 0}, ring[i], ring[(i + 1) % ring.size()]);
    std::vector<uint32_t> left(ring.size());
    for (uint32_t i = 0; i < left.size(); ++i) left[i] = area >= 0 ? i : uint32_t(left.size() - 1 - i);

    auto isEar = [&](size_t k) {
        const size_t n = left.size();
        const uint32_t ia = left[(k + n - 1) % n], ib = left[k], ic = left[(k + 1) % n];
        const Vec2d a = ring[ia], b = ring[ib], c = ring[ic];
        if (cross(a, b, c) <= 0) return false;
        for (uint32_t j : left) {
            const Vec2d p = ring[j];
            if (j == ia || j == ib || j == ic || same(p, a) || same(p, b) || same(p, c)) continue;
            if (inTriangle(p, a, b, c)) return false;
        }
        return true;
    };
    auto clip = [&](size_t k) {
        const size_t n = left.size();
        out.push_back({left[(k + n - 1) % n], left[k], left[(k + 1) % n]});
        left.erase(left.begin() + long(k));
    };
    while (left.size() > 3) {
        size_t ear = left.size();
        for (size_t k = 0; k < left.size() && ear == left.size(); ++k)
            if (isEar(k)) ear = k;
        if (ear == left.size()) {
            const size_t n = left.size();
            for (size_t k = 0; k < n && ear == n; ++k)
                if (cross(ring[left[(k + n - 1) % n]], ring[left[k]], ring[left[(k + 1) % n]]) == 0) ear = k;
        }
        if (ear == left.size()) return {};
        clip(ear);
    }
    out.push_back({left[0], left[1], left[2]});
    return out;
}

} // namespace urbis
