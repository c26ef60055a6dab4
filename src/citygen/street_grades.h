// Streets graded on a terrain (host): the ground a street follows is the terrain averaged over
// kGradeRadius, so that a road rises and falls smoothly along its length through the DEM's noise and
// the fBm's detail, and the terrain under the streets is set to that ground so that it meets them.
#pragma once

#include "citygen/city_mesher.h"
#include "scene/terrain_field.h"

#include <vector>

namespace urbis {

/// Metres over which the ground under the streets is averaged (a tent of this half-width).
inline constexpr float kGradeRadius = 12.0f;

/// The terrain's nx nz heights averaged over a tent of about `radius` metres each way (two box passes
/// along each axis, the grid's edge samples repeated beyond it).
std::vector<float> smoothedHeights(const TerrainField& terrain, float radius);

/// Sets every sample of `terrain` within a sample spacing of `mesh`'s streets at the ground (roads,
/// junctions, sidewalks and curbs whose triangles lie under kAtGround: not bridges' decks and ramps) to
/// `graded` (smoothedHeights), and rebuilds the hierarchy. placeCityOnTerrain then lays them on it.
void gradeStreets(TerrainField& terrain, const CityMesh& mesh, const std::vector<float>& graded);

/// Street triangles wholly below this height (m) on the flat ground lie at the ground, not on a deck.
inline constexpr float kAtGround = 0.5f;

} // namespace urbis
