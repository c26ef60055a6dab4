// Railway attributes from OSM tags.
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace urbis {

/// The kind of track a `railway=*` value names: rail, light_rail, tram, subway, narrow_gauge;
/// nullopt for anything else (abandoned, disused, razed, platform, ...: no rails to draw).
std::optional<RailKind> railKindOf(const char* railway);

/// Railway attributes (all but centerline) of a way whose `railway` names a kind (railKindOf):
/// gauge from `gauge` in mm (the first of a list; else 1000 mm narrow gauge, 1435 mm others),
/// embedded for `embedded=yes|partial` and trams unless `embedded=no`, and the level tags
/// (osm/level_tags.h). Unusable tags are counted in `issues`.
Railway railwayFromTags(const TagLookup& tag, RailKind kind, int64_t osmId, std::map<std::string, uint64_t>& issues);

} // namespace urbis
