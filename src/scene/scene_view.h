// What per-ray code sees of a scene: flat POD arrays and small records, the same on both backends.
#pragma once

#include "geometry/ground_plane.h"
#include "geometry/triangle_scene.h"
#include "geometry/wall_record.h"
#include "lights/sky.h"
#include "lights/sun.h"
#include "scene/material.h"
#include "scene/triangle.h"

namespace urbis {

struct SceneView {
    TriangleSceneView geometry;          ///< BVH nodes and triangles (in the order their leaves reach them)
    const TriangleInfo* triangleInfo;    ///< per triangle, same order as geometry.triangles
    /// Per BVH leaf slot, a PrimRef (kind + index); null when every primitive is a triangle, and
    /// then a leaf slot is the triangle's index.
    const uint32_t* primRefs;
    const WallRecord* walls;             ///< procedural walls, in the order their leaves reach them
    uint32_t wallCount;
    const Material* materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;
};

} // namespace urbis
