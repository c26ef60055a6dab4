// Finding a named OSM feature for the viewer's jumps (`--goto NAME`, a script's "goto", the panel's
// search box): plain code, tested apart from any file or window (tests/place_search_test.cpp).
#pragma once

#include "osm/place_names.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace urbis {

/// Indices into `places` of those whose name holds `query`, ignoring ASCII case and the spaces at its
/// ends, best first: names equal to it, then names that begin with it, then the others, each group
/// in `places`' order; one place per distinct name (its first), at most `limit`. An empty query
/// finds nothing.
std::vector<size_t> findPlaces(const std::vector<NamedPlace>& places, std::string_view query, size_t limit);

} // namespace urbis
