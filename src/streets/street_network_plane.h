// Small plan-view (x east, y north, metres) vector helpers and the point keys that make shared OSM
// nodes one node of the street graph (host).
#pragma once

#include "model/city_model.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>

namespace urbis {

inline Vec2d operator+(Vec2d a, Vec2d b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2d operator-(Vec2d a, Vec2d b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2d operator*(Vec2d a, double s) { return {a.x * s, a.y * s}; }
inline double dot(Vec2d a, Vec2d b) { return a.x * b.x + a.y * b.y; }
/// z of the 3D cross product: > 0 when b turns left of a.
inline double cross(Vec2d a, Vec2d b) { return a.x * b.y - a.y * b.x; }
inline double length(Vec2d a) { return std::hypot(a.x, a.y); }
/// a turned a quarter to the left.
inline Vec2d perpLeft(Vec2d a) { return {-a.y, a.x}; }

/// The exact bits of a point: equal keys are one OSM node (shared points are bit-identical).
struct PointKey {
    uint64_t x = 0, y = 0;
    explicit PointKey(Vec2d p) : x(std::bit_cast<uint64_t>(p.x + 0.0)), y(std::bit_cast<uint64_t>(p.y + 0.0)) {}
    bool operator==(const PointKey&) const = default;
};

struct PointKeyHash {
    size_t operator()(const PointKey& k) const { return std::hash<uint64_t>()(k.x * 0x9e3779b97f4a7c15ull ^ k.y); }
};

/// Where the lines a + s da and b + u db cross: false when they are near parallel (|sin| < minSine).
inline bool crossLines(Vec2d a, Vec2d da, Vec2d b, Vec2d db, double minSine, double& s, double& u) {
    const double det = cross(da, db);
    if (!(std::fabs(det) > minSine * length(da) * length(db))) return false;
    const Vec2d ab = b - a;
    s = cross(ab, db) / det;
    u = cross(ab, da) / det;
    return std::isfinite(s) && std::isfinite(u);
}

} // namespace urbis
