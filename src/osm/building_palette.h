// Colours of buildings whose tags name none: a palette per region (from the city's origin),
// building use and roof form, with per-building variation. A pass after buildCityModel,
// because the origin is known only once the whole file is read. Host only.
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// Broad regions whose untagged buildings share a look.
enum class PaletteRegion : uint8_t { CentralEurope, BritishIsles, SouthernEurope, EasternEurope, NorthAmerica, Other };

/// The region of a city at `origin` (rough lon/lat boxes: Britain and Ireland; Europe south
/// of 45 N; Europe east of 24 E; the rest of Europe; North America); Other when `origin` is
/// invalid or elsewhere.
PaletteRegion paletteRegionOf(const GeoOrigin& origin);

/// The linear colour of an untagged roof of `b` in `region`: flat roofs (Flat, Unknown) are
/// gravel, bitumen, concrete or light membrane greys everywhere; domes copper or lead; pitched
/// roofs of halls, sheds and garages metal or fibre-cement greys; other pitched roofs the
/// region's covering (clay-tile reds and browns, slate and concrete-tile greys in Central
/// Europe; slate with some clay tile in Britain; terracotta in the south; painted metal in
/// the east; asphalt-shingle greys and browns in North America). One palette entry and one
/// of five brightness steps (x0.9 to x1.1) are drawn from b.seed.
Rgb paletteRoofColour(PaletteRegion region, const Building& b);

/// The linear colour of an untagged wall of `b` in `region`: homes in the region's plasters,
/// bricks and renders (whites, creams and ochres in Central Europe, brick, stock brick, stucco
/// and stone in Britain, ...); offices, shops and public buildings in stone, concrete and
/// light greys; untyped buildings (`building=yes`) half as homes, half as offices; churches in stone and brick; halls, sheds and garages in cladding and
/// concrete greys. Drawn from b.seed like the roof, independently of it.
Rgb paletteWallColour(PaletteRegion region, const Building& b);

/// Gives every building of `city` whose wall or roof colour no tag set (Building::
/// wallColourTagged, roofColourTagged) its palette colour for the region of city.origin.
void paintUntaggedBuildings(CityModel& city);

} // namespace urbis
