// What the light BVH (Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive
// Tree Splitting"; pbrt-v4's LightBounds) knows of one light: where it is, how much it emits and
// into which directions. Each light kind gives its own (lights/lamp_light.h, lights/window_light.h).
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

namespace urbis {

/// A light's bounds for the light BVH, as pbrt-v4's LightBounds.
struct LightBounds { Bounds3f bounds; Vec3f axis; float cosThetaO = 1; float cosThetaE = 0; float phi = 0; bool twoSided = false; };

} // namespace urbis
