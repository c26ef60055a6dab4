// Polylines in local metres (x east, y north): length, points along them and sideways offsets, shared
// by every street part that follows a centerline (carriageways, sidewalks, bridges, rails, lamps).
#pragma once

#include "model/city_model.h"

#include <vector>

namespace urbis {

/// Total length in metres.
double polylineLength(const std::vector<Vec2d>& line);

/// The line moved `distance` metres to its left (negative: right), corners mitred; a mitre longer
/// than `mitreLimit` times |distance| is cut to that length (its corner point moved in along the
/// bisector), so acute bends never make spikes. Same point count as `line`.
std::vector<Vec2d> offsetPolyline(const std::vector<Vec2d>& line, double distance, double mitreLimit = 4.0);

/// Unit left normal of the segment a -> b ((0, 0) when a == b).
Vec2d leftNormal(Vec2d a, Vec2d b);

} // namespace urbis
