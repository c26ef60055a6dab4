// The "colliders" light sampler (host+device): the thesis's method ("Direct rendering of procedural
// models", CTU Prague 2021) made sound. There, an invisible sphere of fixed radius around each lamp
// (its collider) sent the rays that entered it to the lamp. Here a shading point light-samples the
// lights whose collider contains it (the light's box within LightListInfo::colliderRadius), chosen
// uniformly among them, and the infinite lights, as the light BVH shares them out; lights that no
// collider brings near are left to BSDF sampling, which MIS weighs. docs/lights.md § Colliders says
// why this stands for the thesis's method. The light BVH's tree serves as the range query.
#pragma once

#include "lights/light_bvh.h"

namespace urbis {

/// Squared distance from `p` to the box `b` (0 inside), square metres.
URBIS_HD inline float distanceSquaredToBox(const Bounds3f& b, Vec3f p) {
    const Vec3f below = vmax(b.lo - p, Vec3f{}), above = vmax(p - b.hi, Vec3f{});
    const Vec3f d = vmax(below, above);
    return dot(d, d);
}

/// Deepest light BVH the traversal's stack holds (the build keeps every trail within 64 bits).
constexpr uint32_t kLightBvhMaxDepth = 64;

/// The lights whose collider contains `p`, in the tree's depth-first order: how many there are, and
/// the one of rank `rank` (kNoLight if rank >= the count; pass kNoLight to count only).
URBIS_HD inline uint32_t collidersAround(const SceneView& scene, Vec3f p, uint32_t rank, uint32_t& count) {
    count = 0;
    if (scene.lightBvhNodes.size == 0) return kNoLight;
    const float r2 = scene.lights.colliderRadius * scene.lights.colliderRadius;
    uint32_t stack[kLightBvhMaxDepth];
    uint32_t top = 0, i = 0;
    for (;;) {
        const LightBvhNode& node = scene.lightBvhNodes[i];
        if (distanceSquaredToBox(node.bounds, p) <= r2) {
            if (node.leaf()) {
                if (count == rank) return node.index();
                ++count;
            } else {
                stack[top++] = node.index();
                i = i + 1;
                continue;
            }
        }
        if (top == 0) return kNoLight;
        i = stack[--top];
    }
}

/// Picks a light for the shading point `p` with one uniform number: its index and probability
/// (kNoLight and 0 where no collider contains p and there is no infinite light).
URBIS_HD inline uint32_t sampleColliderLight(const SceneView& scene, Vec3f p, float u, float& pmf) {
    pmf = 0.0f;
    uint32_t count;
    collidersAround(scene, p, kNoLight, count);
    const float share = infiniteShare(scene, count > 0);
    if (u < share) return pickInfiniteLight(scene, share, u, pmf);
    if (count == 0) return kNoLight;
    const float v = fminf((u - share) / (1.0f - share), kOneMinusEpsilon);
    pmf = (1.0f - share) / float(count);
    uint32_t unused;
    return collidersAround(scene, p, uint32_t(v * float(count)), unused);
}

/// Probability that sampleColliderLight(p) picks light `index`.
URBIS_HD inline float colliderLightPmf(const SceneView& scene, Vec3f p, uint32_t index) {
    uint32_t count;
    collidersAround(scene, p, kNoLight, count);
    const float share = infiniteShare(scene, count > 0);
    uint64_t trail = scene.lightBvhTrails[index];
    if (trail == kNoLightTrail) return isInfiniteLight(scene, index) ? share / float(scene.infiniteLights.size) : 0.0f;
    // The light's own box is its leaf's: follow its trail down.
    const ArrayView<LightBvhNode>& nodes = scene.lightBvhNodes;
    uint32_t i = 0;
    while (!nodes[i].leaf()) {
        i = (trail & 1u) != 0 ? nodes[i].index() : i + 1;
        trail >>= 1;
    }
    const float r2 = scene.lights.colliderRadius * scene.lights.colliderRadius;
    return distanceSquaredToBox(nodes[i].bounds, p) <= r2 ? (1.0f - share) / float(count) : 0.0f;
}

} // namespace urbis
