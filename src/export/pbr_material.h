// urbis's materials as glTF PBR metallic-roughness: the closest standard reading of each kind.
#pragma once

#include "export/export_scene.h"
#include "scene/material.h"

namespace urbis {

/// The PBR material nearest `m`: Lambertian a rough dielectric of its albedo; Glossy its albedo with
/// the roughness of its Phong exponent (Walter et al. 2007: alpha = sqrt(2 / (n + 2)), roughness =
/// sqrt(alpha)); Mirror a smooth metal; Glass a thin transmitting pane; Water a smooth transmitting
/// surface tinted by a metre of its absorption. The emission is kept as it is (urbis units).
PbrMaterial pbrMaterialOf(const Material& m, std::string name);

} // namespace urbis
