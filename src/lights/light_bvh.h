// The light BVH's traversal (host+device): a light picked at a shading point by stochastic descent,
// each child chosen in proportion to its importance there, and the probability of that choice for
// any given light, following the light's bit trail down the same descent. Conty Estevez and Kulla
// 2018, "Importance Sampling of Many Lights with Adaptive Tree Splitting", section 5 (without the
// adaptive splitting); pbrt-v4 BVHLightSampler::Sample and ::PMF. Infinite lights (sun, sky) are not
// in the tree: they take a share of the choices by their power against the tree's. No recursion, no
// allocation.
#pragma once

#include "scene/scene_view.h"

namespace urbis {

/// Where a light is chosen for: the shading point (world, metres) and its unit normal (zero away
/// from a surface, in a medium).
struct LightSampleContext {
    Vec3f p, n;
};

/// cos(a - b) from the sines and cosines of a and b, 1 where a < b (pbrt-v4 cosSubClamped).
URBIS_HD inline float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}

/// sin(a - b) from the sines and cosines of a and b, 0 where a < b (pbrt-v4 sinSubClamped).
URBIS_HD inline float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

/// sqrt(max(0, x)): the sine of an angle from its cosine, safe against rounding past 1.
URBIS_HD inline float sinFromCos(float c) { return sqrtf(fmaxf(0.0f, 1.0f - c * c)); }

/// Importance of a node's lights at `ctx` (Conty Estevez and Kulla 2018, equation 3; pbrt-v4
/// LightBounds::Importance): power over squared distance to the box's centre (clamped to the
/// bounding sphere's squared radius), times the cosine of the smallest angle between a direction of
/// the box's cone of emission and the direction to the point, times the cosine of the smallest angle
/// at the point's normal (absolute: the surface may transmit). Zero where the point lies outside
/// every emitting direction (past theta_o + theta_e).
URBIS_HD inline float lightBvhImportance(const LightBvhNode& node, const LightSampleContext& ctx) {
    const Vec3f pc = node.bounds.centre();
    const Vec3f toP = ctx.p - pc;
    const float d2 = dot(toP, toP);
    const Vec3f diagonal = node.bounds.extent();
    const float radius2 = 0.25f * dot(diagonal, diagonal);
    // Inside the bounding sphere every direction is possible: the angles below are then all 1.
    const float dist = sqrtf(d2);
    const Vec3f wi = dist > 0.0f ? toP / dist : Vec3f{0.0f, 0.0f, 1.0f};
    float cosW = dot(node.axis, wi);
    if (node.twoSided()) cosW = fabsf(cosW);
    const float sinW = sinFromCos(cosW);
    // The cone of directions from the point that the bounding sphere subtends.
    const float cosB = d2 > radius2 ? sqrtf(fmaxf(0.0f, 1.0f - radius2 / d2)) : -1.0f;
    const float sinB = sinFromCos(cosB);
    const float sinO = sinFromCos(node.cosThetaO);
    const float cosX = cosSubClamped(sinW, cosW, sinO, node.cosThetaO);
    const float sinX = sinSubClamped(sinW, cosW, sinO, node.cosThetaO);
    const float cosP = cosSubClamped(sinX, cosX, sinB, cosB);
    if (cosP <= node.cosThetaE) return 0.0f;
    // A point inside the bounding sphere counts as at its surface (pbrt clamps to half the diagonal,
    // a length, instead of its square).
    float importance = node.phi * cosP / fmaxf(fmaxf(d2, radius2), 1e-12f);
    if (ctx.n.x != 0.0f || ctx.n.y != 0.0f || ctx.n.z != 0.0f) {
        const float cosI = fabsf(dot(wi, ctx.n));
        importance *= cosSubClamped(sinFromCos(cosI), cosI, sinB, cosB);
    }
    return fmaxf(importance, 0.0f);
}

/// The colliders' share of the choices for the infinite lights: each counts as much as the whole
/// tree (pbrt-v4's fixed share), `finite` says whether there is anything else to choose.
URBIS_HD inline float infiniteShare(const SceneView& scene, bool finite) {
    const uint32_t n = scene.infiniteLights.size;
    if (n == 0) return 0.0f;
    return float(n) / float(n + (finite ? 1u : 0u));
}

/// Picks one of the infinite lights uniformly with u in [0, share): its index and probability.
URBIS_HD inline uint32_t pickInfiniteLight(const SceneView& scene, float share, float u, float& pmf) {
    const uint32_t n = scene.infiniteLights.size;
    pmf = share / float(n);
    return scene.infiniteLights[uint32_t(fminf(u / share * float(n), float(n - 1)))];
}

/// The light BVH's share of the choices for the infinite lights: their power against the tree's
/// (its root's phi), as the power sampler weighs them; all of them where the tree is empty. pbrt-v4
/// gives each infinite light as much as the whole tree, so that at night a dim sky took half the
/// picks. Fills `infinitePower`, their power together.
URBIS_HD inline float bvhInfiniteShare(const SceneView& scene, float& infinitePower) {
    infinitePower = 0.0f;
    for (uint32_t i = 0; i < scene.infiniteLights.size; ++i) infinitePower += scene.lightRecords[scene.infiniteLights[i]].power;
    if (scene.infiniteLights.size == 0 || !(infinitePower > 0.0f)) return 0.0f;
    if (scene.lightBvhNodes.size == 0) return 1.0f;
    return infinitePower / (infinitePower + scene.lightBvhNodes[0].phi);
}

/// Picks one of the infinite lights in proportion to its power with u in [0, share) (`share` and
/// `infinitePower` from bvhInfiniteShare): its index and probability.
URBIS_HD inline uint32_t pickInfiniteLightByPower(const SceneView& scene, float share, float infinitePower, float u,
                                                  float& pmf) {
    const float target = u / share * infinitePower;
    float sum = 0.0f;
    uint32_t light = scene.infiniteLights[0];
    for (uint32_t i = 0; i < scene.infiniteLights.size; ++i) {
        light = scene.infiniteLights[i];
        sum += scene.lightRecords[light].power;
        if (target < sum && scene.lightRecords[light].power > 0.0f) break;
    }
    pmf = share * scene.lightRecords[light].power / infinitePower;
    return light;
}

/// Whether `light` is one of the infinite lights.
URBIS_HD inline bool isInfiniteLight(const SceneView& scene, uint32_t light) {
    for (uint32_t i = 0; i < scene.infiniteLights.size; ++i)
        if (scene.infiniteLights[i] == light) return true;
    return false;
}

/// The largest float below 1: a number remapped inside [0, 1) stays there.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

/// Probability of the child `second` of an interior node given both children's importances c0, c1
/// (sum > 0). One expression for sampling and for the pmf, so that both give the same bits.
URBIS_HD inline float childProbability(float c0, float c1, bool second) { return (second ? c1 : c0) / (c0 + c1); }

/// Picks a light for `ctx` with one uniform number u in [0, 1): its index into SceneView::lightRecords and
/// the probability of that pick (kNoLight and 0 where nothing there has importance).
URBIS_HD inline uint32_t sampleLightBvh(const SceneView& scene, const LightSampleContext& ctx, float u, float& pmf) {
    pmf = 0.0f;
    float infinitePower;
    const float share = bvhInfiniteShare(scene, infinitePower);
    if (u < share) return pickInfiniteLightByPower(scene, share, infinitePower, u, pmf);
    const ArrayView<LightBvhNode>& nodes = scene.lightBvhNodes;
    if (nodes.size == 0) return kNoLight;
    u = fminf((u - share) / (1.0f - share), kOneMinusEpsilon);
    float p = 1.0f - share;
    for (uint32_t i = 0;;) {
        const LightBvhNode& node = nodes[i];
        if (node.leaf()) {
            // A root that is a leaf has not had its importance checked by a parent.
            if (i > 0 || lightBvhImportance(node, ctx) > 0.0f) {
                pmf = p;
                return node.index();
            }
            return kNoLight;
        }
        const float c0 = lightBvhImportance(nodes[i + 1], ctx);
        const float c1 = lightBvhImportance(nodes[node.index()], ctx);
        if (!(c0 + c1 > 0.0f)) return kNoLight;
        const float p0 = childProbability(c0, c1, false);
        const bool second = !(u < p0);
        const float pc = childProbability(c0, c1, second);
        u = fminf(second ? (u - p0) / pc : u / pc, kOneMinusEpsilon);
        p *= pc;
        i = second ? node.index() : i + 1;
    }
}

/// Probability that sampleLightBvh(ctx) picks light `index`: its bit trail says which child it lies
/// under at each depth, and the same importances give each step's probability.
URBIS_HD inline float lightBvhPmf(const SceneView& scene, const LightSampleContext& ctx, uint32_t index) {
    float infinitePower;
    const float share = bvhInfiniteShare(scene, infinitePower);
    uint64_t trail = scene.lightBvhTrails[index];
    if (trail == kNoLightTrail)
        return isInfiniteLight(scene, index) && share > 0.0f ? share * scene.lightRecords[index].power / infinitePower : 0.0f;
    const ArrayView<LightBvhNode>& nodes = scene.lightBvhNodes;
    float p = 1.0f - share;
    for (uint32_t i = 0;;) {
        const LightBvhNode& node = nodes[i];
        if (node.leaf()) return i > 0 || lightBvhImportance(node, ctx) > 0.0f ? p : 0.0f;
        const float c0 = lightBvhImportance(nodes[i + 1], ctx);
        const float c1 = lightBvhImportance(nodes[node.index()], ctx);
        if (!(c0 + c1 > 0.0f)) return 0.0f;
        const bool second = (trail & 1u) != 0;
        p *= childProbability(c0, c1, second);
        trail >>= 1;
        i = second ? node.index() : i + 1;
    }
}

} // namespace urbis
