// Water surfaces (host): one plane for all water (kWaterLevel), so no two water shapes may overlap
// there: a thin glass pane over another would tint what lies under both twice.
#pragma once

#include "streets/ground_cover_shapes.h"

#include <cstddef>
#include <vector>

namespace urbis {

/// Cuts the `water` shapes of `shapes` so that no two overlap: each loses the area of the smaller
/// ones that lie on it (a river's polygon inside a lake's or a coastline's keeps its own outline, the
/// larger one gets a hole); a `ribbon` (a river drawn from its line, Area::flowLine) loses to every
/// area whatever its size, so that a river mapped both ways is drawn once, as its area. Ties go to the
/// earlier in `water`. Returns, for each entry of `water`, whether anything with area is left of it.
std::vector<bool> separateWaters(CoverShapes& shapes, const std::vector<size_t>& water, const std::vector<bool>& ribbon);

} // namespace urbis
