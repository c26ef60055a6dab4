// What a photon pass needs from the host before photons leave the lights: the sphere the infinite
// lights aim at, the sky's share of the photons when the light list leaves the sky out (by day), and
// the photon buffers' fixed-point scale. docs/photons.md § Emission.
#pragma once

#include "scene/photon_view.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace urbis {

/// The emission sphere (lightSceneSphere, lights/scene_sphere.h) and the
/// sky's share of photons, in a PhotonsView with no map and no buffers.
PhotonsView photonEmissionOf(const Scene& scene, const SceneView& view);

/// Flux (renderer units) that the scene's lights emit into the sphere of `photons`: the sum the
/// photons of a pass estimate.
float photonEmittedFlux(const SceneView& view, const PhotonsView& photons);

/// A buffer texel's integer per unit of irradiance: a photon's splat at level 0 is about 2^30, which
/// leaves 2^34 splats of headroom per texel and resolves a millionth of a photon.
float photonFixedScale(const SceneView& view, const PhotonsView& photons, const RenderSettings& settings);

} // namespace urbis
