// What the light BVH knows of one light (host): where it is, which way it emits and how much. Conty
// Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree Splitting", section
// 4.1; pbrt-v4 LightBounds. Each light kind gives its LightBounds (its bounds, which lightBoundsOf in
// lights/light_build.h dispatches to); the light BVH (lights/light_bvh_build.h) is built from them.
#pragma once

#include "math/bounds.h"

namespace urbis {

/// A light's bounds: `bounds` (world, metres) holds every point that emits; every normal of an
/// emitting point lies within angle theta_o of `axis` (unit), and it emits only within theta_e of
/// its normal; `phi` is its power (LightRecord::power); `twoSided` also emits along -normal.
/// phi = 0: the light is not in the BVH (infinite lights, kinds without bounds).
struct LightBounds { Bounds3f bounds; Vec3f axis; float cosThetaO = 1; float cosThetaE = 0; float phi = 0; bool twoSided = false; };

} // namespace urbis
