// Building footprints on lots: rectangles, L, T, U and courtyard blocks, all rectilinear.
#pragma once

#include "layout/lots.h"
#include "math/hash.h"
#include "model/city_model.h"

namespace urbis {

enum class FootprintShape : uint8_t { Rectangle, L, T, U, Courtyard };

struct Footprint {
    Polygon polygon;  ///< m; outer counter-clockwise, holes clockwise
    FootprintShape shape = FootprintShape::Rectangle;
};

/// A footprint inside `lot`, kept 0.5 m from its sides and back (so neighbouring buildings are
/// at least 1 m apart) and set back from the street by a district-dependent distance; the
/// shape is drawn from `rng` among those that fit.
Footprint makeFootprint(const Lot& lot, HashStream& rng);

} // namespace urbis
