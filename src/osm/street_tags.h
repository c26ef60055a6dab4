// Road and crossing attributes from OSM tags (docs/streets.md, "Street tags").
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace urbis {

/// Road attributes (all but centerline) of a `highway=*` way:
///  - lanes: `lanes`, else the sum of `lanes:forward` and `lanes:backward` (a two-way road's
///    untagged side counts 1), else the class's default (1 when one-way);
///  - width: `width` (with units), else lanes x the class's lane width (motorway and trunk
///    3.5 m, primary and secondary 3.25 m, others 3.0 m) when any lane count is tagged, else
///    the class's default;
///  - sidewalk: `sidewalk`, then `sidewalk:both`, then `sidewalk:left` / `sidewalk:right`, each
///    overriding the sides it names; widths from `sidewalk:width` < `sidewalk:both:width` <
///    `sidewalk:left|right:width`;
///  - surface, footway, lane_markings, overtaking (`no`, or both `overtaking:forward` and
///    `overtaking:backward` `no`), area, and the level tags (osm/level_tags.h).
/// `oneway=-1` sets `reversed`, so the caller flips the centerline (lanes:forward and
/// :backward are swapped to match). Unusable tags are counted in `issues`.
Road roadFromTags(const TagLookup& tag, int64_t osmId, bool& reversed,
                  std::map<std::string, uint64_t>& issues);

/// Whether roads of `highway` carry motor traffic on a carriageway (motorway to living_street,
/// service included): the roads a footway=crossing way crosses.
bool isCarriageway(HighwayClass highway);

/// How a crossing (node, or `footway=crossing` way) is painted, from `crossing`, `crossing_ref`
/// and `crossing:markings`: zebra wherever any says so; else unmarked (`crossing=unmarked`,
/// `crossing:markings=no`); else traffic signals; else marked (`marked`, `uncontrolled`,
/// untagged). nullopt for `crossing=no` (a place where one must not cross).
std::optional<CrossingKind> crossingKindFromTags(const TagLookup& tag);

} // namespace urbis
