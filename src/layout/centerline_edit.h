// Editing generated centerlines: vertices added at given distances along them.
#pragma once

#include "model/city_model.h"

#include <cstddef>
#include <vector>

namespace urbis {

/// A centerline with vertices added, and where they are.
struct CutCenterline {
    std::vector<Vec2d> points;
    std::vector<size_t> vertexAt;  ///< per requested distance, the index in `points` of its vertex
};

/// Adds a vertex to `line` at each of `distances` (metres along it, ascending); an existing vertex
/// within `reuse` metres of one serves instead, so that no segment shorter than that is made.
CutCenterline cutAt(const std::vector<Vec2d>& line, const std::vector<double>& distances, double reuse);

/// The distance in metres along `line` of each of its vertices.
std::vector<double> distancesAlong(const std::vector<Vec2d>& line);

} // namespace urbis
