// The streets of a city, all parts together: the one entry point citygen calls.
#pragma once

#include "streets/street_mesh.h"

namespace urbis {

/// Meshes every street part of `city` (street_mesh.h lists them). Deterministic: the same city and
/// options give the same mesh, whatever the thread count.
StreetMesh meshStreets(const CityModel& city, const StreetOptions& options);

} // namespace urbis
