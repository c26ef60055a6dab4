// Typical heights of buildings by type and region: what an untagged building gets when too
// few tagged buildings of its type stand nearby. Pure tables, tested on their own.
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// Where a city lies, as far as the heights of its untagged buildings go.
enum class Region : uint8_t { Other, Europe, NorthAmerica, EastAsia };

/// The region of a point (degrees, WGS84) from coarse boxes: Europe 34..72 N, 25 W..60 E;
/// North America 15..72 N, 170..50 W; East Asia 0..55 N, 95..150 E; else Other.
Region regionOf(double lat, double lon);

/// Heights in metres above the base, roof included.
struct HeightSpan {
    float min = 0, max = 0;
};

/// The span of typical heights of a building type in a region (the type's Other row where the
/// region has none of its own). Examples: a house 6-10 m (1-2 storeys and a roof), a European
/// residential block 13-19 m (4-6 storeys), a North American one 6-12 m (mostly houses), a
/// warehouse 6-10 m, a church's nave 12-20 m, a garage 3 m, a shed 2.5 m.
HeightSpan typicalHeight(BuildingType type, Region region);

} // namespace urbis
