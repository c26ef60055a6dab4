// Heights, uses, roofs, materials and colours of generated buildings.
#pragma once

#include "layout/footprint_shapes.h"
#include "layout/lots.h"
#include "math/hash.h"
#include "model/city_model.h"

namespace urbis {

/// Metres per storey used to derive `levels` from a height.
inline constexpr float kStoreyHeight = 3.2f;

/// Height range in metres of the generated buildings.
struct HeightRange {
    float min = 8.0f, max = 120.0f;
};

/// Sets height (m, taller toward the centre: a Gaussian falloff of `normalisedRadius`, the
/// distance from the centre over the city radius, in log space, times a lognormal jitter, clamped to `range`),
/// levels, roof, type, material and colours of `b`, whose footprint is already set.
void styleBuilding(Building& b, const Lot& lot, FootprintShape shape, double normalisedRadius,
                   HeightRange range, HashStream& rng);

} // namespace urbis
