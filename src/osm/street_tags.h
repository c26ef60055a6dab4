// Road and street-lamp attributes from OSM tags.
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <map>
#include <string>

namespace urbis {

/// Road attributes (all but centerline) of a `highway=*` way. Width: `width` (with
/// units), else lanes x 3.25 m when `lanes` is tagged, else the class's default; lanes:
/// `lanes`, else the class's default (1 when one-way). `oneway=-1` sets `reversed`, so the
/// caller flips the centerline. Unusable tags are counted in `issues`.
Road roadFromTags(const TagLookup& tag, int64_t osmId, bool& reversed,
                  std::map<std::string, uint64_t>& issues);

/// Lamp attributes (all but position) of a `highway=street_lamp` node: `height`, else a
/// height by `lamp_mount`; `lamp_type` or `light:method`; `light:count`; `light:colour`.
Lamp lampFromTags(const TagLookup& tag, int64_t osmId);

} // namespace urbis
