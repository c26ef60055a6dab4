// Tree and green/water area attributes from OSM tags.
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <optional>

namespace urbis {

/// Tree attributes (all but position) of a `natural=tree` node or a `natural=tree_row` way:
/// `height`, `diameter_crown` and `circumference` (with units) over the defaults, `leaf_type` and
/// `leaf_cycle` (semi_deciduous as deciduous, semi_evergreen as evergreen).
Tree treeFromTags(const TagLookup& tag, int64_t osmId);

/// `leaf_type`: broadleaved, needleleaved (mixed, leafless and anything else: Unknown).
LeafType leafTypeFromTags(const TagLookup& tag);

/// The width (m) of the water ribbon drawn for a river mapped as a line: `width` where it parses, else
/// by `waterway`: river 12, canal 8, stream 3, drain and ditch 1.5; nullopt for any other waterway and
/// for one in a tunnel (tunnel=culvert|yes|...: under the ground, not drawn).
std::optional<float> waterwayWidthFromTags(const TagLookup& tag);

/// The kind of ground a closed way or multipolygon covers; nullopt for none. Tags are tried in
/// this order, and the first that names a kind wins (docs/streets.md, "Street tags"):
///  1. water: natural=water|wetland, waterway=riverbank, water=*, landuse=basin|reservoir: a
///     polygon that says it is water is water, whatever landuse it also carries;
///  2. pedestrian: area:highway=*, place=square, and highway=* with area=yes (on a multipolygon
///     relation highway=* alone): squares and plazas;
///  3. parking: amenity=parking, unless parking=underground|multi-storey;
///  4. leisure (the use of this very place): pitch, playground, park|garden -> Park;
///  5. natural (what grows there): sand|beach -> Sand, scrub|heath -> Scrub, wood -> Forest,
///     grassland -> Grass;
///  6. landuse (the broadest, often under the others): forest, cemetery,
///     grass|meadow|village_green -> Grass, farmland|farmyard -> Farmland, residential,
///     commercial|retail -> Commercial, industrial|railway -> Industrial.
/// A `highway` way without area=yes is a road, never an area.
std::optional<AreaKind> areaKindFromTags(const TagLookup& tag);

} // namespace urbis
