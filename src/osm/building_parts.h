// building:part replaces the building outline it lies in (Simple 3D Buildings rule).
#pragma once

#include "model/city_model.h"
#include "model/geos_polygon.h"

#include <map>
#include <string>
#include <vector>

namespace urbis {

/// Removes every building outline (isPart false) that holds a part: the part's centroid
/// lies inside the outline (outer ring, not in a hole), or more than half of the part's
/// area overlaps it. Each removed outline is recorded as "replaced_by_parts" in `dropped`.
/// Outlines are found through a uniform grid, so this is near linear in the count.
void replaceOutlinesByParts(std::vector<Building>& buildings, const GeosContext& geos,
                            ReasonLog& dropped);

} // namespace urbis
