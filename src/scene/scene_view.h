// What per-ray code sees of a scene: flat POD arrays and small records, the same on both backends.
#pragma once

#include "geometry/ground_plane.h"
#include "geometry/triangle_scene.h"
#include "lights/sky.h"
#include "lights/sun.h"
#include "scene/material.h"
#include "scene/triangle.h"

namespace urbis {

struct SceneView {
    TriangleSceneView geometry;          ///< BVH nodes and triangles in leaf order
    const TriangleInfo* triangleInfo;    ///< per triangle, same order as geometry.triangles
    const Material* materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;
};

} // namespace urbis
