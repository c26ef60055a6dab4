// Light records (host+device POD) and the view of the scene's light arrays. A light is a tag and an
// index into the array of its kind; the functions over them (sampling, pdf) live in lights/.
#pragma once

#include "math/piecewise_constant.h"
#include "math/vec.h"
#include "scene/lamp_record.h"
#include "scene/light_bvh_node.h"

#include <cstdint>

namespace urbis {

/// The closed set of light kinds; lights/light.h dispatches on it with a switch.
enum class LightKind : uint32_t {
    Sun,              ///< SceneView::sun: a disk of directions
    Sky,              ///< SceneView::sky: the environment, importance-sampled from its radiance
    Moon,             ///< SceneView::night.moon: a disk of directions, as the sun
    EmissiveSurface,  ///< LightsView::surfaces[index]: the triangles of one emitting material
    Point,            ///< LightsView::lampLights[index]: a street lamp, a point with a profile by head shape
    Spot,             ///< reserved: spot lamps (with a cone and profile), not built yet
    Aggregate,        ///< SceneView::walls[index]: the lit windows of one wall record (tile), as one light
};

/// One light of the sampler's list.
struct LightRecord {
    LightKind kind = LightKind::Sun;
    uint32_t index = 0;  ///< into the array of its kind (0 for the sun, the moon and the sky)
    float power = 0;     ///< luminous flux in the renderer's units (lights/light_build.cpp says how)
    uint32_t litCells = 0;  ///< Aggregate: the lit cells of its tile, which its sampler picks among (lights/window_light.h)
};

/// An emitting surface: triangles of one emitting material, sampled uniformly by area. It emits
/// `emission` from both sides, as materials do. buildLights makes one per emitting triangle, so that
/// the light BVH can tell near emitters from far ones (docs/lights.md § Emitting triangles).
struct EmissiveSurface {
    Vec3f emission;
    uint32_t firstTriangle = 0, triangleCount = 0;  ///< range of LightsView::triangles
    float area = 0;                                 ///< total, square metres
};

/// A triangle of an EmissiveSurface, with the cumulative share of its surface's area up to and
/// including it, so that a triangle is picked in proportion to its area by a binary search.
struct TriangleLight {
    Vec3f p0, p1, p2;
    float cdf = 0;
};

/// A street lamp as a light (lights/lamp_light.h): a point at its glass whose intensity follows a
/// profile by head shape, made from a LampRecord at scene build (lights/light_build.cpp).
struct LampEmitter {
    Vec3f position;          ///< world, metres: the glass's centre
    Vec3f intensity;         ///< at the profile's peak, renderer units (radiance x m^2, docs/lights.md § Units)
    float glassRadius = 0;   ///< the glass's radius, metres (a disc's, a globe's, a lantern's widest)
    float glassHeight = 0;   ///< a lantern's glass's height, metres; 0 for the others
    /// Shadow rays towards the point stop this far short of it, so that the lamp's own glass does
    /// not block them: the radius of a sphere about the point holding the glass.
    float clearance = 0;
    LampShape shape = LampShape::Cobra;
};

constexpr uint32_t kNoLight = 0xffffffffu;

/// A light-sampled emitting triangle: its index in SceneView::triangles and its light. Sorted by
/// triangle, so that the light a BSDF sample found is a binary search (lights/light_sampler.h).
struct EmitterTriangle {
    uint32_t triangle = 0, light = 0;
};

/// What per-ray code sees of the scene's lights. Not built (buildLights was not called), it stands
/// for the list {sun}: the sun is light-sampled, the sky and emitters are found by BSDF sampling
/// and counted in full (the path tracer's estimator before MIS).
struct LightsView {
    bool built = false;
    const LightRecord* records = nullptr;
    uint32_t count = 0;
    PiecewiseConstant1DView power;                ///< over records: the power-weighted choice
    const EmissiveSurface* surfaces = nullptr;
    const TriangleLight* triangles = nullptr;
    const LampEmitter* lampLights = nullptr;        ///< per lamp record (SceneView::lamps), when lamps are lights
    /// Lamp i is light firstLampLight + i and wall record i light firstWallLight + i (kNoLight: none are).
    uint32_t firstLampLight = kNoLight, firstWallLight = kNoLight;
    const EmitterTriangle* emitterTriangles = nullptr;  ///< sorted by triangle
    uint32_t emitterCount = 0;
    const LightBvhNode* bvhNodes = nullptr;       ///< the light BVH over the lights of finite extent (lights/light_bvh.h)
    uint32_t bvhNodeCount = 0;
    const uint64_t* bvhTrails = nullptr;          ///< per light: its path from the root (bit d: second child at depth d), or kNoLightTrail
    const uint32_t* infiniteLights = nullptr;     ///< the lights the BVH leaves out that are sampled apart (sun, sky)
    uint32_t infiniteCount = 0;
    float colliderRadius = 0;                     ///< metres: the colliders sampler's sphere about each light (lights/collider_lights.h)
    PiecewiseConstant2DView skyTable;             ///< over (u, v) of the sky's equal-area map (lights/sky_light.h)
    uint32_t sunLight = 0, skyLight = kNoLight;   ///< their places in records, or kNoLight
    uint32_t moonLight = kNoLight;
};

} // namespace urbis
