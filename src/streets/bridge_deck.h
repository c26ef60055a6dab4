// The structure of a deck that follows a centerline above the ground: its side faces and underside (a
// slab under the top that the carriageway and sidewalks draw), parapets on both edges and abutments
// where it lands; or, for a ramped approach, walls down to the ground (an embankment). Shared by road
// and railway bridges.
#pragma once

#include "model/city_model.h"
#include "scene/triangle_mesh.h"

#include <vector>

namespace urbis {

/// Thickness of a deck's slab under its top, m.
inline constexpr float kDeckThickness = 1.0f;
/// A parapet's height above the deck's top at its edge, and its thickness, m.
inline constexpr float kParapetHeight = 1.05f;
inline constexpr float kParapetThickness = 0.3f;

/// The world point of local metres `p` (x east, y north) at height `h`: x = east, y = up, z = -north.
inline Vec3f worldFromStreet(Vec2d p, double h) { return {float(p.x), float(h), float(-p.y)}; }

/// Adds the quad a b c d (in order around it) as two triangles; returns 2.
size_t addQuad(TriangleMesh& mesh, Vec3f a, Vec3f b, Vec3f c, Vec3f d, TriangleInfo info);

/// Adds the ribbon between lines `a` (at heights hA per point) and `b` (at hB), two triangles a
/// segment (none where both lines repeat a point): a top or underside between two edges, or a vertical
/// band when a and b are one line. Returns the triangles added.
size_t addRibbon(TriangleMesh& mesh, const std::vector<Vec2d>& a, const std::vector<float>& hA,
                 const std::vector<Vec2d>& b, const std::vector<float>& hB, TriangleInfo info);

/// Heights `base` plus `offset` at every point.
std::vector<float> raised(const std::vector<float>& base, float offset);

/// A line fit to mesh: two or more points within 10,000 km of the origin, over 1 cm long.
bool meshableLine(const std::vector<Vec2d>& line);

/// A deck's cross-section along a centerline.
struct DeckShape {
    double leftWidth = 0, rightWidth = 0;  ///< m from the centerline to the deck's left / right edge
    float leftLevel = 0, rightLevel = 0;   ///< m above the elevation of the top at the left / right edge
    bool embankment = false;               ///< side walls down to the ground, no underside (an approach)
    bool top = false;                      ///< a top between the edges at the left edge's level (railways)
    bool closeStart = false, closeEnd = false;  ///< an abutment (ground to top) and parapet ends there
};

/// Meshes the deck of `line` (local metres) at `elevation` (m per point, roadElevations): side faces
/// from the slab's underside (kDeckThickness under the carriageway's level, kRoadLevel + elevation; the
/// ground for an embankment) to the top at each edge's level,
/// the underside, parapets on both edges and the abutments asked for. Edges are offsetPolyline's, as
/// the surfaces on top use. `deck` tags the slab, `parapet` the parapets. Returns the triangles added.
size_t meshDeck(const std::vector<Vec2d>& line, const std::vector<float>& elevation, const DeckShape& shape,
                TriangleInfo deck, TriangleInfo parapet, TriangleMesh& mesh);

/// meshDeck as an embankment (`shape` with embankment set) along each run of the ground way's segments
/// that are lifted (elevation > 0 at either end): an approach's ramp. Returns the triangles added.
size_t meshEmbankments(const std::vector<Vec2d>& line, const std::vector<float>& elevation, DeckShape shape,
                       TriangleInfo deck, TriangleInfo parapet, TriangleMesh& mesh);

} // namespace urbis
