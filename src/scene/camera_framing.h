// Host-side ways of placing the camera: automatic framing, and by heading and pitch.
#pragma once

#include "math/bounds.h"
#include "scene/camera.h"

namespace urbis {

/// An elevated three-quarter view (from the south-west, 22 degrees down) that fits `cityBounds`
/// (world space) in the frame.
Camera frameCity(const Bounds3f& cityBounds, float fovYDeg, float aspect);

/// A camera at world `position` looking along a heading (degrees clockwise from north) and a
/// pitch (degrees above the horizon; negative looks down).
Camera cameraFromHeading(Vec3f position, float headingDeg, float pitchDeg, float fovYDeg, float aspect);

} // namespace urbis
