// The interior straight skeleton of a footprint (with holes), from CGAL, as plain arrays:
// the roof faces of hipped, pyramidal and mansard roofs and the inset ring of parapets.
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace urbis {

/// Skeleton vertices and faces in the city plane. Contour vertices are the footprint's own points
/// (bit-identical), with time 0; skeleton vertices closer than 1 µm are merged into one.
struct StraightSkeleton {
    std::vector<Vec2d> points;
    std::vector<double> times;                  ///< m: offset distance at which the wavefront reaches the vertex
    std::vector<std::vector<uint32_t>> faces;   ///< one counter-clockwise ring of point indices per contour edge
    double maxTime = 0;                         ///< m: the largest time (half the width of the widest part)
};

/// Footprints with more vertices than this (all rings) get no skeleton: CGAL's time and memory
/// grow faster than the vertex count, and no building needs that many.
inline constexpr size_t kMaxSkeletonVertices = 4096;

/// The interior straight skeleton of `footprint` (outer ring counter-clockwise, holes clockwise and
/// strictly inside; cleanFootprint makes it so), by CGAL's Straight_skeleton_builder_2 with the
/// Exact_predicates_inexact_constructions_kernel (Aichholzer & Aurenhammer, "Straight skeletons for
/// general polygonal figures", 1996). Returns nothing when CGAL cannot build it: degenerate input,
/// a CGAL exception, more than kMaxSkeletonVertices, or more events than a skeleton needs.
std::optional<StraightSkeleton> interiorStraightSkeleton(const Polygon& footprint);

} // namespace urbis
