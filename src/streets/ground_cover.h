// Ground cover, paved areas and water (host): every Area of the city as flat triangles over the
// ground, on planes chosen so that areas that overlap never share one.
#pragma once

#include "scene/surface_part.h"
#include "streets/street_materials.h"
#include "streets/street_mesh.h"

namespace urbis {

/// How an area kind is drawn: its material, surface part and place among the flat areas.
struct CoverStyle {
    /// Which plane an area lies on (street_levels.h): the ground cover's stack, the water's surface
    /// (with its bed below the ground, streets/water_depth.h), or the paved areas' stack.
    enum class Band { Ground, Water, Paved };
    Band band = Band::Ground;
    /// Ground band: higher lies above lower where they overlap (landuse 0, vegetation and sand 1,
    /// pitches and playgrounds 2, parking 3).
    int priority = 0;
    StreetMaterial material = StreetMaterial::ResidentialGround;
    SurfacePart part = SurfacePart::GroundCover;
};

/// The style of `area`: by kind, and for parking and pedestrian areas by `surface` (a pedestrian
/// area without one is paving stones).
CoverStyle coverStyleOf(const Area& area);

/// Meshes every area of `city` into `out`: its polygon (holes kept) triangulated by GEOS, flat at
/// its band's plane. Ground cover lies from kGroundCoverLevel up by kCoverStep: sorted by priority,
/// then larger first (a park inside a park lies above it), each one step above the highest earlier
/// one it overlaps. Water lies at waterSurfaceLevel, cut where a smaller water lies on it, over its
/// bed (StreetMaterial::WaterBed, meshWaterBed with options.water) below the ground; paved pedestrian areas stack from
/// kPavedAreaLevel. Object ids run from options.firstObject + out.objects in the areas' order and
/// out.objects grows by the areas meshed. Counts `ground_cover` and `water` (areas) with their
/// triangles; areas left out are counted in out.dropped: `area_degenerate` (no area once made
/// valid, or coordinates beyond CoverShapes::kMaxCoordinate), `area_hole_degenerate` (a hole
/// skipped), `water_covered` (all under smaller water), `area_under_water` (ground cover all under
/// water, which cuts itself out of the ground cover it overlaps), `area_too_deep` (a pile deeper than its
/// band's planes), `area_triangulation_failed`.
void meshGroundCover(const CityModel& city, const StreetOptions& options, StreetMesh& out);

} // namespace urbis
