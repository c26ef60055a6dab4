// Builds a scene's light list and tables on the host (Scene::lights), once its geometry, materials,
// sun and sky are set: each light kind of LightKinds adds its lights in the list's order (its
// addLights: which join, their power and the kind's arrays), then the power table and the light BVH
// over every light of finite extent (URBIS_LIGHT_ARRAYS of scene_arrays.h, and Scene::lights).
#pragma once

#include "lights/scene_sphere.h"
#include "scene/light_bounds.h"
#include "scene/scene.h"

#include <cstddef>
#include <functional>

namespace urbis {

struct LightBuildOptions {
    bool sun = true, sky = true, surfaces = true;  ///< which kinds join the list (tests leave some out)
    bool moon = true;                              ///< where it shines: above the horizon (NightSky::moon)
    uint32_t skyWidth = 128, skyHeight = 64;       ///< cells of the sky's table in azimuth and polar angle
    bool compensateSky = true;                     ///< the sky's table holds what exceeds its mean (lights/sky_light.h)
    /// The sky joins the list only where its (compensated) power is at least this share of the sun's
    /// and its own together (lights/sky_light.h); 0: wherever its table is not empty.
    float skyMinShare = 0.5f;
    /// Street lamps (LampLight) and walls of lit windows (WindowLight) join the list when the sun is
    /// below this elevation (degrees) or off: at dusk and at night. By day lit rooms are still found by
    /// BSDF sampling (counted in full) and lamps do not shine.
    float nightBelowElevation = 6.0f;
    bool lamps = true, windows = true;
    /// Radius of the colliders sampler's sphere about each light, metres (lights/collider_lights.h).
    float colliderRadius = 30.0f;
};

/// What each light kind's addLights (host) is handed: the scene, whose light arrays it fills (empty
/// when it begins), the options, and the list so far.
struct LightListBuilder {
    Scene& scene;
    const LightBuildOptions& options;
    /// Of lightSceneSphere: an infinite light's power is its radiance through the sphere's disk
    /// (pbrt-v4 DistantLight::Phi), pi radius^2.
    double radius = 1;
    /// Whether the night's lights shine: the sun below options.nightBelowElevation or off.
    bool night = false;

    /// Appends light `index` of kind `kind` (into the kind's array) with `power`; returns its place in
    /// the list. A kind's lights come one after another (LightListInfo::firstOfKind).
    uint32_t add(uint32_t kind, uint32_t index, float power, uint32_t litCells = 0);
    /// Calls f(i) for every i in [0, n), in parallel.
    void parallelFor(size_t n, const std::function<void(size_t)>& f) const;
};

/// Fills the light arrays of `scene` (URBIS_LIGHT_ARRAYS) and scene.lights from the rest of it. What is
/// left out of the list is still found by BSDF sampling and counted in full; so is an emitting
/// material that a wall or the ground also uses (their emission cannot be light-sampled yet). A sky of
/// the atmosphere model whose tables were not built (buildAtmosphere) gets them first: the sky's
/// table is made from them.
void buildLights(Scene& scene, const LightBuildOptions& options = {});

/// The light BVH's input for one light of the list (scene/light_bounds.h): its kind's bounds.
/// Infinite lights have phi 0 (not in the tree).
LightBounds lightBoundsOf(const Scene& scene, const LightRecord& light);

} // namespace urbis
