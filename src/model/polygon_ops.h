// Plain 2D polygon operations on local metres: cleaning, orientation, area, centroid.
#pragma once

#include "model/city_model.h"

namespace urbis {

/// Removes consecutive duplicate points and the closing point (a repeated first point).
void removeDuplicatePoints(Ring& ring);

/// Signed area in m^2 (shoelace): positive when counter-clockwise (x east, y north).
double signedArea(const Ring& ring);

/// Area in m^2 of the outer ring minus the holes.
double area(const Polygon& polygon);

/// Area-weighted centroid of a ring; the mean of its points when the area is zero.
Vec2d centroid(const Ring& ring);

/// Whether a point lies inside a ring (even-odd rule).
bool contains(const Ring& ring, Vec2d p);

/// Whether a point lies inside a polygon: in its outer ring and in none of its holes.
bool contains(const Polygon& polygon, Vec2d p);

/// Turns the outer ring counter-clockwise and the holes clockwise.
void orient(Polygon& polygon);

/// The point of segment a-b nearest p (a when a = b).
Vec2d nearestOnSegment(Vec2d p, Vec2d a, Vec2d b);

/// Distance from p to the segment a-b.
double distanceToSegment(Vec2d p, Vec2d a, Vec2d b);

/// Axis-aligned box of a ring: {min, max}.
std::array<Vec2d, 2> bounds(const Ring& ring);

} // namespace urbis
