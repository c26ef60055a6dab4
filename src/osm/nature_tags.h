// Tree and green/water area attributes from OSM tags.
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <optional>

namespace urbis {

/// Tree attributes (all but position) of a `natural=tree` node: `height` and
/// `diameter_crown` (with units) over the defaults.
Tree treeFromTags(const TagLookup& tag, int64_t osmId);

/// The kind of area a closed way or multipolygon stands for: leisure=park|garden -> Park,
/// landuse=grass|meadow -> Grass, landuse=forest and natural=wood -> Forest,
/// natural=water and waterway=riverbank -> Water; nullopt for anything else.
std::optional<AreaKind> areaKindFromTags(const TagLookup& tag);

} // namespace urbis
