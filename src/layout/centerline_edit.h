// Editing generated centerlines: vertices added at spots along them. A spot is kept relative to
// its segment's own vertices, never as a distance from the line's start, so that the same segment
// in a larger city (whose line starts farther out) gets the same point, bit for bit.
#pragma once

#include "model/city_model.h"

#include <cstddef>
#include <vector>

namespace urbis {

/// A point on a centerline: `offset` metres from vertex `segment` toward vertex `segment + 1`.
struct Spot {
    size_t segment = 0;
    double offset = 0;
};

/// The spot `metres` along `line` from `from` (backward when negative), stopping at its ends.
Spot advance(const std::vector<Vec2d>& line, Spot from, double metres);

/// A centerline with vertices added, and where they are.
struct CutCenterline {
    std::vector<Vec2d> points;
    std::vector<size_t> vertexAt;  ///< per requested spot, the index in `points` of its vertex
};

/// Adds a vertex to `line` at each of `spots` (in order along it); an existing vertex within
/// `reuse` metres of one serves instead, so that no segment shorter than that is made.
CutCenterline cutAt(const std::vector<Vec2d>& line, const std::vector<Spot>& spots, double reuse);

} // namespace urbis
