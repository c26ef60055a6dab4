// The plane geometry of the ground cover through GEOS (host): areas made valid, their overlaps, water
// cut where a smaller water lies on it, and triangles (constrained Delaunay of the rings only).
#pragma once

#include "model/city_model.h"

#include <array>
#include <cstddef>
#include <vector>

struct GEOSContextHandle_HS;  // geos_c.h's context type, kept out of this header
struct GEOSGeom_t;            // geos_c.h's geometry type

namespace urbis {

/// A triangle in local metres (x east, y north).
using PlaneTriangle = std::array<Vec2d, 3>;

/// Axis-aligned box in local metres: {min, max}.
using PlaneBox = std::array<Vec2d, 2>;

/// Whether two boxes share more than an edge.
bool boxesOverlap(const PlaneBox& a, const PlaneBox& b);

/// Valid polygonal shapes, numbered in the order they were added; owns its GEOS context, so one per
/// thread. Not copyable.
class CoverShapes {
public:
    CoverShapes();
    ~CoverShapes();
    CoverShapes(const CoverShapes&) = delete;
    CoverShapes& operator=(const CoverShapes&) = delete;

    /// What add() made of a polygon.
    enum class Added { Shape, Degenerate };

    /// Adds `polygon` made valid (GEOSMakeValid_r, every polygonal part kept: a self-touching ring
    /// becomes two polygons, or one with a hole). Degenerate, and nothing added, when a coordinate is
    /// not finite or beyond kMaxCoordinate, the outer ring has fewer than three points, or no area is
    /// left. A hole of fewer than three points is skipped and counted in holesSkipped.
    Added add(const Polygon& polygon);

    size_t size() const { return shapes_.size(); }
    /// m^2.
    double area(size_t shape) const;
    const PlaneBox& box(size_t shape) const { return shapes_[shape].box; }

    /// Whether the interiors of two shapes share area (shapes that only touch along edges do not).
    bool overlap(size_t a, size_t b) const;

    /// Removes `cut`'s area from `shape`; false when nothing with area is left of it.
    bool subtract(size_t shape, size_t cut);

    /// The shape's triangles: GEOS's constrained Delaunay triangulation of its rings' points (none
    /// added inside), so a coastline's polygon gives its point count in triangles. Empty on failure.
    std::vector<PlaneTriangle> triangles(size_t shape) const;

    /// The shape's triangles for a surface that varies near its boundary (a water's bed): the shape
    /// cut into pieces of at most `cell` metres across wherever it comes within `band` metres of its
    /// boundary, in larger pieces beyond (halvings of its box, so that a piece's edges meet its
    /// neighbours' vertices there), each triangulated as triangles() does. Empty on failure.
    std::vector<PlaneTriangle> trianglesNearBoundary(size_t shape, double cell, double band) const;

    /// Metres from each of `points` to the shape's boundary (outer ring and holes).
    std::vector<double> distancesToBoundary(size_t shape, const std::vector<Vec2d>& points) const;

    /// Holes skipped by add() for having fewer than three points.
    size_t holesSkipped = 0;

    /// Coordinates beyond this many metres from the origin make a polygon degenerate (no extract
    /// spans 10,000 km, and floats would lose the centimetres that the levels are apart).
    static constexpr double kMaxCoordinate = 1.0e7;

private:
    struct Shape {
        GEOSGeom_t* geometry;
        PlaneBox box;
    };
    GEOSContextHandle_HS* handle_;
    std::vector<Shape> shapes_;
};

} // namespace urbis
