// `urbis render --planet`: a whole planet's prepared scene from the description (docs/planets.md).
#pragma once

#include "prepare/prepared_scene.h"

namespace urbis {

/// The planet of `d.planet` (which must be set) with its camera, sun and atmosphere, ready to render.
PreparedScene preparePlanetScene(const SceneDescription& d);

} // namespace urbis
