// What per-ray code sees of a scene: flat POD arrays and small records, the same on both backends.
#pragma once

#include "geometry/ground_plane.h"
#include "geometry/triangle_scene.h"
#include "geometry/wall_record.h"
#include "scene/light_records.h"
#include "scene/material.h"
#include "scene/sky.h"
#include "scene/sun.h"
#include "scene/triangle.h"

namespace urbis {

struct SceneView {
    TriangleSceneView geometry;          ///< BVH nodes and triangles (in the order their leaves reach them)
    const TriangleInfo* triangleInfo;    ///< per triangle, same order as geometry.triangles
    /// Per BVH leaf slot, a PrimRef (kind + index); null when every primitive is a triangle, and
    /// then a leaf slot is the triangle's index.
    const uint32_t* primRefs;
    const WallRecord* walls;             ///< procedural walls, in the order their leaves reach them
    const Material* materials;
    GroundPlane ground;
    Sun sun;
    Sky sky;
    LightsView lights;                   ///< the light sampler's list and tables (empty: sun and sky)
};

/// The view of a scene's arrays, host vectors or device buffers alike (anything with data() and
/// size()); an empty primRefs becomes null.
SceneView makeSceneView(const auto& nodes, const auto& triangles, const auto& triangleInfo, const auto& primRefs,
                        const auto& walls, const auto& materials, const GroundPlane& ground, const Sun& sun,
                        const Sky& sky, const LightsView& lights = {}) {
    return SceneView{TriangleSceneView{nodes.data(), triangles.data(), uint32_t(triangles.size())},
                     triangleInfo.data(),
                     primRefs.size() == 0 ? nullptr : primRefs.data(),
                     walls.data(),
                     materials.data(),
                     ground,
                     sun,
                     sky,
                     lights};
}

} // namespace urbis
