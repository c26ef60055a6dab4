// Builds the light BVH on the host (Conty Estevez and Kulla 2018, section 4; pbrt-v4
// BVHLightSampler::buildBVH): a binary tree over the lights' LightBounds, split where the
// orientation-aware surface area cost (pbrt-v4 EvaluateCost) is least, laid out as the flat
// LightBvhNode array that per-ray code reads (lights/light_bvh.h), with each light's bit trail.
#pragma once

#include "scene/light_bounds.h"
#include "scene/light_bvh_node.h"
#include "scene/light_records.h"

#include <vector>

namespace urbis {

/// The light BVH's arrays (scene_arrays.h: lightBvhNodes, lightBvhTrails).
struct LightBvh {
    std::vector<LightBvhNode> nodes;  ///< depth-first; empty when no light has bounds
    std::vector<uint64_t> trails;     ///< per light: bit d set where it lies under the second child at depth d; kNoLightTrail if not in the tree
};

/// The union of two lights' bounds: both boxes, a cone of normals holding both cones, the narrower
/// emission spread's complement (the larger theta_e), the sum of the powers. A bound of no power is
/// nothing (pbrt-v4 Union(LightBounds, LightBounds) and Union(DirectionCone, DirectionCone)).
LightBounds unionLightBounds(const LightBounds& a, const LightBounds& b);

/// The tree over `lights` (one LightBounds per light of the list, by index): lights of power 0 are
/// left out. Deterministic: the same bounds give the same nodes.
LightBvh buildLightBvh(const std::vector<LightBounds>& lights);

} // namespace urbis
