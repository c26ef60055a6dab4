// The roof shapes of Simple 3D Buildings as stored triangles over a footprint, each sitting on the
// wall top `sink.base` and closing the building with the walls: every footprint edge at the wall
// top is shared by exactly one roof or gable triangle.
#pragma once

#include "citygen/roof_surface.h"
#include "citygen/straight_skeleton.h"
#include "model/city_model.h"

#include <array>
#include <vector>

namespace urbis {

/// Triangles of a footprint in the city plane (GEOS's constrained Delaunay triangulation).
using FootprintTriangles = std::vector<std::array<Vec2d, 3>>;

/// A flat roof: the footprint triangles at the wall top.
void meshFlatRoof(const FootprintTriangles& footprint, RoofSink& sink);

/// One footprint edge's share of a parapet's top: the edge p0 -> p1 (as in the footprint's ring)
/// and the points q0, q1 where the parapet's top meets the deck's edge, on the straight skeleton's
/// arcs from p0 and p1 at the parapet's thickness: the quad p0 p1 q1 q0.
struct ParapetBand {
    Vec2d p0, p1, q0, q1;
};

/// A flat roof behind a parapet: the parapet's top (`thickness` m wide, the straight skeleton's
/// offset band) at the wall top, its inner face, and the deck `parapetHeight` m lower. An edge
/// whose band is the quad p0 p1 q1 q0 (its skeleton face has no vertex nearer than `thickness`
/// but the edge's own) is not meshed but appended to `bands`, for its wall to carry
/// (WallRecord::parapetHeight) or meshParapetBand to mesh. Returns false (emitting nothing) when a
/// triangle of a skeleton face cannot be found.
bool meshParapetRoof(const StraightSkeleton& skeleton, double parapetHeight, double thickness, RoofSink& sink,
                     std::vector<ParapetBand>& bands);

/// The parapet's top over `band` and its inner face down to the deck, as four wall triangles.
void meshParapetBand(const ParapetBand& band, double parapetHeight, RoofSink& sink);

/// A roof whose height is `profile` of s = dot(p, across) (skillion, gabled, gambrel, round), over
/// the footprint triangles, with vertical walls (gables) wherever it stands above a footprint edge.
/// s within 0.1 µm of a breakpoint is snapped to it so that eaves meet the walls exactly.
void meshRidgeRoof(const Polygon& polygon, const FootprintTriangles& footprint, Vec2d across,
                   const RoofProfile& profile, RoofSink& sink);

/// A roof whose height is `profile` of the straight-skeleton time (hipped, pyramidal, mansard).
/// Returns false (emitting nothing) when a skeleton face cannot be triangulated.
bool meshSkeletonRoof(const StraightSkeleton& skeleton, const RoofProfile& profile, RoofSink& sink);

/// A gabled roof over a footprint of several wings (L, T, U...): the hipped roof of the straight
/// skeleton with each wing's end hip turned into a vertical gable, its apex moved onto the end's
/// edge at its own height (so the ridge runs to the gable). A footprint without wing ends (a ring
/// around a courtyard) keeps the skeleton's roof, its ridge running all round. `profile` maps
/// skeleton time to height and must be linear. Returns false (emitting nothing) when a face cannot
/// be triangulated.
bool meshGabledSkeletonRoof(const StraightSkeleton& skeleton, const RoofProfile& profile, RoofSink& sink);

/// A pyramid over a convex ring: one triangle per edge up to the area centroid, `height` m above the wall top.
void meshPyramidRoof(const Ring& outer, double height, RoofSink& sink);

/// One point of a surface of revolution: the ring scaled by `scale` about the centroid, `height` m up.
struct RevolutionStep {
    double scale, height;
};

/// A dome or onion over a convex ring: copies of the ring scaled about its area centroid at each
/// step (the first must be {1, 0}, the last {0, top}), joined by quads, closed at the apex.
void meshRevolvedRoof(const Ring& outer, const std::vector<RevolutionStep>& steps, RoofSink& sink);

} // namespace urbis
