// What of a built scene depends on the date and time of day: the sun, the moon and the stars, the
// sky with its atmosphere's tables, the lit windows and the light list. Set once when the scene is
// prepared, and again for each frame of an animation whose time of day moves (docs/animation.md),
// without building the geometry or its BVH again.
#pragma once

#include "citygen/window_schedule.h"
#include "description/scene_description.h"
#include "model/city_model.h"
#include "scene/scene.h"

#include <span>

namespace urbis {

/// Sets the sun, the moon and the stars of `d` (celestialLightsOf, seen from the city at `origin`),
/// its sky and the atmosphere's tables for that sun, and builds the light list, over a scene whose
/// geometry and clouds are set. The same description gives the same scene whatever it held before
/// (the atmosphere's sun-free tables of an earlier lightScene are kept where the medium is the same:
/// they have the bits a fresh build gives).
void lightScene(Scene& scene, const SceneDescription& d, const GeoOrigin& origin);

/// Sets each procedural wall's chance of lit rooms and lit shop windows for `hour` (local clock) by
/// its building's use, `uses[object - 1]`, as meshCity does: the windows of another hour without
/// meshing again. Call before lightScene, whose light list holds the walls of lit windows.
void relightWindows(Scene& scene, std::span<const WindowUse> uses, float hour);

} // namespace urbis
