// Small hand-written .osm files for import tests: nodes, ways and tags as XML text.
#pragma once

#include "process_scratch_dir.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

namespace urbis::test {

/// Writes `body` (nodes, ways, relations) into an .osm file under the test temp dir,
/// with a <bounds> box of about 220 x 220 m at lon 10.0, lat 50.0.
inline std::string writeOsm(const std::string& name, const std::string& body) {
    const std::filesystem::path path = processScratchDir() / name;
    std::ofstream(path) << "<?xml version='1.0' encoding='UTF-8'?>\n<osm version='0.6' generator='test'>\n"
                        << "<bounds minlat='50.0' minlon='10.0' maxlat='50.002' maxlon='10.003'/>\n"
                        << body << "</osm>\n";
    return path.string();
}

/// A node at (lon, lat) given in millionths of a degree above (10.0, 50.0).
inline std::string node(int id, int dLon, int dLat, const std::string& tags = "") {
    return "<node id='" + std::to_string(id) + "' version='1' lat='" + std::to_string(50.0 + dLat * 1e-6) +
           "' lon='" + std::to_string(10.0 + dLon * 1e-6) + "'>" + tags + "</node>\n";
}

inline std::string way(int id, std::initializer_list<int> nodes, const std::string& tags) {
    std::string s = "<way id='" + std::to_string(id) + "' version='1'>";
    for (int n : nodes) s += "<nd ref='" + std::to_string(n) + "'/>";
    return s + tags + "</way>\n";
}

inline std::string tag(const std::string& k, const std::string& v) { return "<tag k='" + k + "' v='" + v + "'/>"; }

/// The first record of `items` with this OSM id, or nullptr.
template <typename T>
const T* findById(const std::vector<T>& items, int64_t osmId) {
    const auto it = std::find_if(items.begin(), items.end(), [osmId](const T& item) { return item.osmId == osmId; });
    return it == items.end() ? nullptr : &*it;
}

} // namespace urbis::test
