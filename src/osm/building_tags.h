// Building attributes from OSM tags: heights, levels, roof, type, material, colours.
#pragma once

#include "model/city_model.h"
#include "osm/import_options.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <map>
#include <string>

namespace urbis {

/// Per-object seed: a 32-bit hash (splitmix64) of the import seed and the OSM id.
uint32_t objectSeed(uint32_t seed, int64_t osmId);

/// Every Building field except footprint and isPart, from the tags of a building or a
/// building:part (metres, linear colours).
/// Height: `height`, else (`building:levels` + roof) x metresPerLevel, else a placeholder
/// marked HeightSource::TypeTable that estimateHeights (osm/height_estimate.h) replaces.
/// Base: `min_height`, else `building:min_level` x metresPerLevel. Roof height:
/// `roof:height`, else `roof:levels` x metresPerLevel, else one level for pitched shapes.
/// Colours: the colour tag, else the material's colour (wallColourTagged, roofColourTagged);
/// else left for paintUntaggedBuildings (building_palette.h).
/// Unusable tags are ignored and counted in `issues` ("bad_height_tag", ...).
Building buildingFromTags(const TagLookup& tag, const ImportOptions& options, int64_t osmId,
                          std::map<std::string, uint64_t>& issues);

} // namespace urbis
