// Street lamps into the streets' mesh (host): a model Lamp as an analytic LampRecord, or as its
// triangle twin, with its light's colour temperature and flux for the night.
#pragma once

#include "scene/lamp_record.h"
#include "streets/street_mesh.h"

#include <string>
#include <vector>

namespace urbis {

/// A lamp's light by its method (`lamp_type` / `light:method`): high-pressure sodium 2000 K and
/// 15000 lm, low-pressure sodium 1800 K, mercury 4100 K, metal halide 4200 K, fluorescent 4000 K,
/// incandescent and halogen 2700 K, gas 2200 K, LED (and anything unknown) 4000 K and 8000 lm; per light.
struct LampLight {
    float colourTemperature;   ///< K
    float luminousFlux;        ///< lm
};
LampLight lampLightOf(const std::string& lampType);

/// The record of `lamp` (model metres: x east, y north; world x, -z): the pole's foot on the ground
/// plane (a sidewalk's 25 cm hide its bottom, and a lamp never floats where there is no curb), a
/// pole's radius by height, an arm by mount (bent masts 25 % of the height, 1-3 m; cobra and flat
/// heads on a plain pole 15 %; wall lamps 0.6 m from the wall), a head sized by height, leaning to
/// `direction` (east when untold). The tagged colour temperature wins over the method's.
LampRecord lampRecordOf(const Lamp& lamp, uint32_t object, uint32_t firstMaterial);

/// Adds `lamps` to `out`: each its own object, as records in out.lamps (options.lamps Procedural)
/// or as its twin's triangles in out.mesh; counts["lamps"], and trianglesByKind["lamps"] for
/// triangles. A lamp with a non-finite position or height goes to dropped["lamp_bad_geometry"].
void addLamps(const std::vector<Lamp>& lamps, const StreetOptions& options, StreetMesh& out);

} // namespace urbis
