// The river of a generated city: a meandering band of water running west to east, north or south
// of the centre. It depends only on the seed, so a larger city has the same river.
#pragma once

#include "layout/layout_geometry.h"
#include "model/city_model.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace urbis {

/// How far in metres (across the river, north or south) a junction stays from the water: enough
/// for a bridge's 15 m landing and a crossing road's corridor, so that no junction is on a bridge.
inline constexpr double kRiverJunctionClearance = 45.0;

class River {
public:
    /// Seeded: 40-80 m wide, meandering 60-110 m either side of its course, 150-450 m from the centre.
    static River generate(uint32_t seed);
    /// y in metres of the middle of the river at x.
    double middleAt(double x) const;
    /// Signed distance in metres from p to the water's edge, measured north-south: negative in the water.
    double distance(Vec2d p) const;
    /// The water's extent in y (metres, south then north) on the north-south line at x.
    std::pair<double, double> across(double x) const { return {middleAt(x) - halfWidth_, middleAt(x) + halfWidth_}; }
    /// Whether rectangle r (metres) comes within `margin` metres (north-south) of the water.
    bool near(const Rect2d& r, double margin) const;
    /// The water between x0 and x1 as a counter-clockwise polygon, a vertex every 10 m of x.
    Ring polygon(double x0, double x1) const;
    /// The river's middle between x0 and x1, a point every 10 m of x, west to east: the way it flows.
    std::vector<Vec2d> flowLine(double x0, double x1) const;
    /// Whether the water comes within `radius` metres of (0, 0).
    bool reaches(double radius) const;

private:
    double course_ = 0;            // m, mean y of the middle
    double halfWidth_ = 30;        // m, north-south
    double amplitude_[2] = {}, wavenumber_[2] = {}, phase_[2] = {};
    double reach() const { return amplitude_[0] + amplitude_[1] + halfWidth_; }  // m, course to farthest water
    double steepest() const { return amplitude_[0] * wavenumber_[0] + amplitude_[1] * wavenumber_[1]; }
};

} // namespace urbis
