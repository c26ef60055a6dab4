// Roofs as piecewise-planar height fields. Each roof triangle in the city plane carries a scalar s
// per vertex (distance across the ridge, or straight-skeleton time), linear over the triangle; the
// height is a piecewise-linear function of s. Every triangle is cut where s crosses a breakpoint,
// so each piece is planar. A crossing is computed from its edge's endpoints taken in a fixed
// order, so two triangles that share an edge cut it at bit-identical points and the mesh stays
// watertight.
#pragma once

#include "scene/triangle_mesh.h"
#include "model/city_model.h"

#include <array>
#include <functional>
#include <vector>

namespace urbis {

/// A point of the city plane (m) with the scalar that drives its height.
struct LevelPoint {
    Vec2d p;
    double s = 0;
};

/// Height above the wall top as a piecewise-linear function of s: breakpoints `s` (increasing, m)
/// and heights `h` (m); constant beyond the ends; heights under 0.1 mm are 0.
struct RoofProfile {
    std::vector<double> s, h;
    /// Height at `x`, m.
    double at(double x) const;
    /// The interior breakpoints, where triangles must be cut.
    std::vector<double> cuts() const { return s.size() > 2 ? std::vector<double>(s.begin() + 1, s.end() - 1) : std::vector<double>{}; }
};

/// Where one roof's stored triangles go, with heights measured from the wall top `base` (m).
struct RoofSink {
    TriangleMesh& mesh;
    TriangleInfo roofInfo, wallInfo;
    double base = 0;
    size_t roofTriangles = 0, wallTriangles = 0;

    /// World point over city point `p` at `h` m above the wall top.
    Vec3f at(Vec2d p, double h) const;
    /// Appends a roof triangle (world space).
    void roof(Vec3f a, Vec3f b, Vec3f c);
    /// Appends a wall triangle (gables, parapets; world space).
    void wall(Vec3f a, Vec3f b, Vec3f c);
};

/// Appends a, then the points where s crosses each of `cuts` (sorted) strictly between s(a) and
/// s(b), in order from a to b; b itself is not appended. The crossings do not depend on the
/// direction the edge is walked in.
void appendCutEdge(LevelPoint a, LevelPoint b, const std::vector<double>& cuts, std::vector<LevelPoint>& out);

/// Calls `piece(points, slab)` for each non-empty part of `triangle` between consecutive `cuts`
/// (slab 0 below cuts[0], slab cuts.size() above the last); each part is convex, its points in
/// the triangle's order, crossings included.
void forEachSlab(const std::array<LevelPoint, 3>& triangle, const std::vector<double>& cuts,
                 const std::function<void(const std::vector<LevelPoint>&, size_t)>& piece);

/// Emits `triangle` as roof triangles lifted by `profile`, cut at its breakpoints.
void emitProfiledTriangle(const std::array<LevelPoint, 3>& triangle, const RoofProfile& profile, RoofSink& sink);

/// Emits the vertical wall between the wall top and the roof over the footprint edge a-b (a gable,
/// or the high side of a skillion): bottom edge a-b alone, top edge cut like the roof's. Nothing
/// where the roof meets the edge at the wall top. The roof height along an edge must be concave.
void emitWallUnderRoof(LevelPoint a, LevelPoint b, const RoofProfile& profile, RoofSink& sink);

} // namespace urbis
