// Reading an OSM file in two passes with libosmium.
#pragma once

#include "osm/import_options.h"
#include "osm/raw_features.h"

#include <string>

namespace urbis {

/// Reads an OSM file (format from its name) into RawFeatures: pass 1 gives the relations
/// to osmium::area::MultipolygonManager, pass 2 sets node locations (FlexMem index) and
/// collects nodes, ways and assembled multipolygons. Throws whatever libosmium throws.
RawFeatures readOsm(const std::string& path, const ImportOptions& options);

} // namespace urbis
