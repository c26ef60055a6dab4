#include "layout/river.h"

#include "math/hash.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace urbis {

namespace {

constexpr double kSampleStep = 2.0;   // m of x between samples when testing rectangles
constexpr double kPolygonStep = 10.0; // m of x between the polygon's vertices

} // namespace

River River::generate(uint32_t seed) {
    River r;
    HashStream rng{hash2(seed, 0x41e7u)};
    r.halfWidth_ = rng.uniform(20.0f, 40.0f);
    r.amplitude_[0] = rng.uniform(50.0f, 90.0f);
    r.amplitude_[1] = rng.uniform(10.0f, 20.0f);
    r.wavenumber_[0] = 2.0 * std::numbers::pi / rng.uniform(1000.0f, 1600.0f);
    r.wavenumber_[1] = 2.0 * std::numbers::pi / rng.uniform(400.0f, 600.0f);
    r.phase_[0] = 2.0 * std::numbers::pi * rng.uniform();
    r.phase_[1] = 2.0 * std::numbers::pi * rng.uniform();
    // Far enough from the centre that the main east-west street and the centre's junction stay dry.
    const double course = r.reach() + kRiverJunctionClearance + rng.uniform(20.0f, 250.0f);
    r.course_ = rng.uniform() < 0.5f ? course : -course;
    return r;
}

double River::middleAt(double x) const {
    return course_ + amplitude_[0] * std::sin(wavenumber_[0] * x + phase_[0]) +
           amplitude_[1] * std::sin(wavenumber_[1] * x + phase_[1]);
}

double River::distance(Vec2d p) const { return std::abs(p.y - middleAt(p.x)) - halfWidth_; }

bool River::near(const Rect2d& r, double margin) const {
    const double reachWithMargin = reach() + margin;
    if (r.y1 < course_ - reachWithMargin || r.y0 > course_ + reachWithMargin) return false;
    // Between samples the middle moves at most steepest() * half a step.
    const double band = halfWidth_ + margin + steepest() * 0.5 * kSampleStep;
    const int steps = static_cast<int>(std::ceil((r.x1 - r.x0) / kSampleStep));
    for (int i = 0; i <= steps; ++i) {
        const double m = middleAt(std::min(r.x1, r.x0 + i * kSampleStep));
        if (m + band >= r.y0 && m - band <= r.y1) return true;
    }
    return false;
}

Ring River::polygon(double x0, double x1) const {
    const int steps = std::max(1, static_cast<int>(std::ceil((x1 - x0) / kPolygonStep)));
    Ring ring;
    for (int i = 0; i <= steps; ++i) {  // the south bank eastward
        const double x = x0 + (x1 - x0) * i / steps;
        ring.push_back({x, middleAt(x) - halfWidth_});
    }
    for (int i = steps; i >= 0; --i) {  // the north bank westward
        const double x = x0 + (x1 - x0) * i / steps;
        ring.push_back({x, middleAt(x) + halfWidth_});
    }
    return ring;
}

std::vector<Vec2d> River::flowLine(double x0, double x1) const {
    const int steps = std::max(1, static_cast<int>(std::ceil((x1 - x0) / kPolygonStep)));
    std::vector<Vec2d> line;
    for (int i = 0; i <= steps; ++i) {
        const double x = x0 + (x1 - x0) * i / steps;
        line.push_back({x, middleAt(x)});
    }
    return line;
}

bool River::reaches(double radius) const { return std::abs(course_) - reach() < radius; }

} // namespace urbis
