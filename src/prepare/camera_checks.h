// Sanity checks of the camera against the city: inside a building, under the ground, far away.
#pragma once

#include "math/bounds.h"
#include "model/city_model.h"
#include "scene/camera.h"

#include <string>
#include <vector>

namespace urbis {

/// Metres beyond the city's horizontal diagonal, measured from its centre, where a camera
/// counts as far from the city.
inline constexpr float kFarCameraMargin = 1000.0f;

/// What is wrong with `camera` for `city` (whose meshed world bounds are `cityBounds`), one
/// line each, empty when nothing is: the camera lies inside a building (in its footprint,
/// between its min height and height), below the ground plane (y < 0), or farther from the
/// centre of `cityBounds`, horizontally, than their horizontal diagonal + kFarCameraMargin.
std::vector<std::string> cameraProblems(const Camera& camera, const CityModel& city, const Bounds3f& cityBounds);

} // namespace urbis
