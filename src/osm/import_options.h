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
    /// Buildings without height or levels tags get an estimate from their neighbours and a
    /// table of types (osm/height_estimate.h); with this range {min, max} in metres they get
    /// instead a height seeded by (seed, osm id) uniform in it above their base (the thesis's
    /// --building-min-h / --building-max-h).
    std::optional<std::array<float, 2>> untaggedHeightRange;
    /// Metres per storey: `building:levels`, `roof:levels` and `building:min_level` are
    /// multiplied by it.
    float metresPerLevel = 3.0f;
    /// Seed of everything random: building seeds and height variations hash (seed, osm id).
    uint32_t seed = 1;
};

} // namespace urbis
