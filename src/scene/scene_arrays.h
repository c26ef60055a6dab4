// The one description of a scene's arrays: (record type, member name, stats key) per line. It makes
// the members of Scene (host vectors), SceneView (pointers), DeviceScene (device buffers) and
// SceneMemory (bytes), and their forEach; so a new array is one line here.
#pragma once

#include "accel/wide_bvh_node.h"
#include "scene/cloud_layer.h"
#include "scene/light_bvh_node.h"
#include "scene/light_records.h"
#include "scene/material.h"
#include "scene/prim_kinds.h"
#include "scene/road_segment.h"

#include <cstdint>

// What buildLights makes (lights/light_build.h): the light list, each light kind's arrays, the light
// BVH and the sky's table. A new light kind's arrays go here.
#define URBIS_LIGHT_ARRAYS(X)                          \
    X(LightRecord, lightRecords, "light_records")      \
    X(float, lightPower, "light_power")                \
    X(EmissiveSurface, emissiveSurfaces, "emissive_surfaces") \
    X(TriangleLight, triangleLights, "triangle_lights") \
    X(LampEmitter, lampLights, "lamp_lights")            \
    X(EmitterTriangle, emitterTriangles, "emitter_triangles") \
    X(LightBvhNode, lightBvhNodes, "light_bvh")        \
    X(uint64_t, lightBvhTrails, "light_bvh_trails")    \
    X(uint32_t, infiniteLights, "infinite_lights")     \
    X(float, skyTable, "sky_table")

// X(Type, member, "stats key"): in leaf order where the BVH's leaves reach them.
#define URBIS_SCENE_ARRAYS(X)                          \
    X(WideBvhNode, nodes, "bvh")                       \
    X(uint32_t, leafSlots, "leaf_slots")               \
    X(Triangle, triangles, "triangles")                \
    X(TriangleInfo, triangleInfo, "triangle_info")     \
    X(WallRecord, walls, "walls")                      \
    X(GroundRecord, grounds, "grounds")                \
    X(LampRecord, lamps, "lamps")                      \
    X(Material, materials, "materials")                \
    X(RoadSegment, roadSegments, "road_segments")      \
    URBIS_LIGHT_ARRAYS(X)                              \
    X(Vec3f, transmittanceLut, "transmittance_lut")    \
    X(Vec3f, multiScatteringLut, "multiscattering_lut") \
    X(Vec3f, skyViewLut, "sky_view_lut")               \
    X(TerrainRecord, terrains, "terrain_records")      \
    X(float, terrainData, "terrain")                  \
    X(TreeRecord, trees, "trees")                     \
    X(PlanetRecord, planets, "planets")                \
    X(ForestRecord, forests, "forests")                \
    X(CloudLayer, cloudLayers, "cloud_layers")         \
    X(CloudNoiseTexel, cloudNoise, "cloud_noise")      \
    X(float, cloudCoverage, "cloud_coverage")          \
    X(float, cloudMajorants, "cloud_majorants")

namespace urbis {

/// A non-owning view of one array (host+device POD).
template <typename T>
struct ArrayView {
    const T* data = nullptr;
    uint32_t size = 0;

    URBIS_HD const T& operator[](uint32_t i) const { return data[i]; }
};

/// The array of kind Record's records among `arrays` (a Scene, a SceneView or a DeviceScene): one
/// line per kind.
template <typename Record>
URBIS_HD auto& kindArray(auto& arrays) {
    if constexpr (std::is_same_v<Record, Triangle>) return arrays.triangles;
    else if constexpr (std::is_same_v<Record, WallRecord>) return arrays.walls;
    else if constexpr (std::is_same_v<Record, GroundRecord>) return arrays.grounds;
    else if constexpr (std::is_same_v<Record, LampRecord>) return arrays.lamps;
    else if constexpr (std::is_same_v<Record, TerrainRecord>) return arrays.terrains;
    else if constexpr (std::is_same_v<Record, TreeRecord>) return arrays.trees;
    else if constexpr (std::is_same_v<Record, PlanetRecord>) return arrays.planets;
    else {
        static_assert(std::is_same_v<Record, ForestRecord>, "a kind of PrimKinds without its array here");
        return arrays.forests;
    }
}

} // namespace urbis
