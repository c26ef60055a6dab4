// Host-side ways of placing the camera: automatic framing, and by heading and pitch.
#pragma once

#include "math/bounds.h"
#include "scene/camera.h"

#include <span>

namespace urbis {

/// Share of the image's half width and half height that frameCity leaves free on each side.
inline constexpr float kFramingMargin = 0.03f;

/// An elevated three-quarter view (from the south-west, 22 degrees down) of `cityBounds` (world
/// space) from the least distance at which all 8 corners of the bounds project inside the image,
/// kFramingMargin from its edges, for this field of view and aspect; the corners' extent on
/// the image is centred on both axes.
Camera frameCity(const Bounds3f& cityBounds, float fovYDeg, float aspect);

/// frameCity over the union of `pieces` (world space; empty ones ignored): every corner of every
/// piece inside the image. Pieces that follow the city's shape (CityMesh::framingPieces) frame it
/// tighter than its one box, whose far top and near bottom corners may hold no building.
Camera frameCity(std::span<const Bounds3f> pieces, float fovYDeg, float aspect);

/// A camera at world `position` looking along a heading (degrees clockwise from north) and a
/// pitch (degrees above the horizon; negative looks down).
Camera cameraFromHeading(Vec3f position, float headingDeg, float pitchDeg, float fovYDeg, float aspect);

} // namespace urbis
