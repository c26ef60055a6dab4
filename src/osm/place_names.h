// The named features of an OSM file (their `name` tags): where the viewer can jump by name
// (docs/viewer.md). Read apart from the city's import, when the viewer first looks for a name.
#pragma once

#include <string>
#include <vector>

namespace urbis {

/// A named OSM feature: a node at its location, a way at the mean of its nodes, a relation at the
/// mean of its member ways' nodes.
struct NamedPlace {
    std::string name;
    double lon = 0, lat = 0;   ///< degrees, WGS84
};

/// The named nodes and ways of the OSM file at `path`, in file order, then its named relations
/// (a forest mapped as a multipolygon, say) in file order. A way or relation whose nodes are all
/// missing from the file is left out. Throws InputError "PATH: problem" on a file it cannot read.
std::vector<NamedPlace> readPlaceNames(const std::string& path);

} // namespace urbis
