// The city a scene description names, and how it is meshed: shared by the commands that render it
// (render, bench, view) and the one that exports it.
#pragma once

#include "citygen/city_mesher.h"
#include "description/scene_description.h"
#include "model/city_model.h"

#include <cstddef>

namespace urbis {

/// The city of `d.source`: imported from OSM or generated, the description's colour overrides
/// applied and every height scaled by its height scale. Throws InputError.
CityModel loadSceneCity(const SceneDescription& d);

/// The meshing options `d` asks for (geometry modes, materials, streets, traffic side, the hour of
/// the lit rooms, water, trees); the triangle twin limited to `memoryLimit` bytes (0: no limit).
CityMeshOptions cityMeshOptionsOf(const SceneDescription& d, size_t memoryLimit);

} // namespace urbis
