// The sea of an extract (host): OSM's natural=coastline ways, land on their left, joined end to end
// and closed against the extract's box into sea polygons (as osmcoastline does for the planet).
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace urbis {

/// One natural=coastline way in local metres (x east, y north), in its OSM direction: land on the left.
struct CoastlineWay {
    int64_t osmId = 0;
    std::vector<Vec2d> points;
};

/// What seaPolygons made, and what it had to repair.
struct SeaPolygons {
    std::vector<Polygon> sea;             ///< counter-clockwise outer rings, islands as holes
    std::vector<std::string> warnings;    ///< one line per repair or drop, naming the way
    std::vector<int64_t> extendedWays;    ///< ways whose chain ended inside the box and was carried to its edge
    std::vector<int64_t> droppedWays;     ///< ways whose pieces could not be closed into a ring
};

/// The sea inside the box [boxMin, boxMax] (local metres) that `ways` bound. Ways sharing an end
/// point are joined into chains. A closed chain inside the box is an island (counter-clockwise) or a
/// sea within land (clockwise). Open chains are clipped to the box; a chain that ends inside it (a
/// broken or truncated coastline) is carried straight to the nearest edge, with a warning. The
/// pieces, reversed so the sea lies on their left, are linked by walking the box's edge
/// counter-clockwise from each piece's end to the next piece's start, which closes each sea's ring;
/// islands become holes of the sea around them. Without open chains the box is sea if the largest
/// ring is an island, land otherwise. No coastline: no sea.
SeaPolygons seaPolygons(const std::vector<CoastlineWay>& ways, Vec2d boxMin, Vec2d boxMax);

} // namespace urbis
