// Options of the OSM importer (what to crop to, how to fill in missing heights).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

namespace urbis {

struct ImportOptions {
    /// Crop box in degrees: minLon, minLat, maxLon, maxLat. Default: the file header's box,
    /// else the extent of the file's nodes.
    std::optional<std::array<double, 4>> bbox;
    /// Range in metres of the seeded height given to buildings without height or levels
    /// tags (the thesis's --building-min-h / --building-max-h).
    float minBuildingHeight = 20.0f, maxBuildingHeight = 100.0f;
    /// Metres per storey: `building:levels`, `roof:levels` and `building:min_level` are
    /// multiplied by it.
    float metresPerLevel = 3.0f;
    /// Seed of everything random: building seeds and seeded heights hash (seed, osm id).
    uint32_t seed = 1;
};

} // namespace urbis
