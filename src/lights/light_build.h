// Builds a scene's light list and tables on the host (Scene::lights), once its geometry, materials,
// sun and sky are set: the sun, the moon and the sky where they shine, one EmissiveSurface per
// emitting triangle, lamps and walls of lit windows at night, each light's power, the sky's
// importance table and the light BVH (light arrays of
// scene_arrays.h, and Scene::lights beside them).
#pragma once

#include "scene/light_bounds.h"
#include "scene/scene.h"

namespace urbis {

struct LightBuildOptions {
    bool sun = true, sky = true, surfaces = true;  ///< which kinds join the list (tests leave some out)
    bool moon = true;                              ///< where it shines: above the horizon (NightSky::moon)
    uint32_t skyWidth = 128, skyHeight = 64;       ///< cells of the sky's table in azimuth and polar angle
    bool compensateSky = true;                     ///< the sky's table holds what exceeds its mean (light_build.cpp)
    /// The sky joins the list only where its (compensated) power is at least this share of the sun's
    /// and its own together (light_build.cpp); 0: wherever its table is not empty.
    float skyMinShare = 0.5f;
    /// Street lamps (Point lights) and walls of lit windows (Aggregate lights) join the list when the
    /// sun is below this elevation (degrees) or off: at dusk and at night. By day lit rooms are still
    /// found by BSDF sampling (counted in full) and lamps do not shine.
    float nightBelowElevation = 6.0f;
    bool lamps = true, windows = true;
    /// Radius of the colliders sampler's sphere about each light, metres (lights/collider_lights.h).
    float colliderRadius = 30.0f;
};

/// Fills the light arrays of `scene` (scene_arrays.h) and scene.lights from the rest of it. What is left out of the list is still found by
/// BSDF sampling and counted in full; so is an emitting material that a wall or the ground also
/// uses (their emission cannot be light-sampled yet). A sky of the atmosphere model whose tables
/// were not built (buildAtmosphere) gets them first: the sky's table is made from them.
void buildLights(Scene& scene, const LightBuildOptions& options = {});

/// The light BVH's input for one light of the list (scene/light_bounds.h): one function per kind
/// behind a switch. Infinite lights (sun, sky) and kinds without bounds have phi 0 (not in the tree).
LightBounds lightBoundsOf(const Scene& scene, const LightRecord& light);

} // namespace urbis
