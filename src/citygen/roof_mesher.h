// One building's roof as stored triangles: the shape from roof:shape (Simple 3D Buildings), its
// height from roof:height / roof:levels / roof:angle or a default pitch per shape, its ridge from
// roof:direction / roof:orientation, and the walls' top below it.
#pragma once

#include "citygen/roof_shapes.h"
#include "scene/triangle_mesh.h"
#include "model/city_model.h"

#include <vector>

namespace urbis {

/// What meshRoof appended.
struct RoofResult {
    double wallTop = 0;                    ///< m above ground where the walls end (height - roof height)
    size_t roofTriangles = 0;              ///< roof surface (roof material)
    size_t wallTriangles = 0;              ///< gables, skillion high sides, parapets (wall material)
    std::vector<const char*> fallbacks;    ///< why the roof was meshed as a simpler shape, if it was
    double parapetHeight = 0;              ///< m from the deck to the parapet's top (the wall top); 0: none
    double parapetThickness = 0;           ///< m
    std::vector<ParapetBand> parapetBands; ///< parapet tops not meshed: the walls' to carry or mesh
};

/// Height in m of a roof of `shape` on `building` whose footprint has straight-skeleton depth `depth`
/// m (half the width of its widest part) and half span `halfSpan` m across its ridge: roof:height or
/// roof:levels if the importer set them, else `depth` or `halfSpan` x tan(roof:angle), else a default
/// pitch per shape (40 degrees; skillion 15 over the whole span; dome and onion a hemisphere, 2.5x
/// taller), capped at half the building's height; never more than height - minHeight.
double roofHeightOf(const Building& building, RoofShape shape, double depth, double halfSpan);

/// Appends the roof of `building` over its footprint triangles, with the gables that close it on
/// the walls; the walls must end at the returned wallTop, where the roof's edges meet them exactly.
/// Ridge roofs (skillion, gabled, gambrel, round) are height profiles across the ridge over the whole
/// footprint, with vertical gables wherever the roof stands above a footprint edge; hipped, mansard,
/// and pyramidal on non-convex footprints follow the straight skeleton; dome and onion are rings
/// scaled about the centroid on convex near-square footprints (else hipped); flat roofs of buildings
/// taller than 8 m get a parapet. An unknown shape falls back to flat; where CGAL cannot build the
/// skeleton, hipped and mansard fall back to pyramidal on convex footprints, else to flat, and a
/// parapet to a plain flat roof; each reason is listed in `fallbacks`.
RoofResult meshRoof(const Building& building, const FootprintTriangles& footprint, TriangleInfo roofInfo,
                    TriangleInfo wallInfo, TriangleMesh& mesh);

} // namespace urbis
