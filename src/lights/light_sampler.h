// The light sampler (host+device): picks one light of the scene's list for next-event estimation at
// a shading point and says with what probability it picks a given one there, for MIS.
#pragma once

#include "lights/collider_lights.h"
#include "lights/light_bvh.h"
#include "scene/integrator_choice.h"
#include "scene/scene_view.h"

namespace urbis {

/// Lights in the list; a view not built stands for {sun}.
URBIS_HD inline uint32_t lightCount(const LightsView& lights) { return lights.built ? lights.count : 1u; }

/// The record of light `index` of the list.
URBIS_HD inline LightRecord lightRecord(const LightsView& lights, uint32_t index) {
    if (lights.built) return lights.records[index];
    return LightRecord{LightKind::Sun, 0, 0.0f};
}

/// Probability that selectLight(ctx) picks light `index` (kNoLight: 0). The light BVH and the
/// colliders need built lights; without them they fall back to Uniform, as Power does.
URBIS_HD inline float lightSelectionPmf(const LightsView& lights, LightSamplerKind kind, const LightSampleContext& ctx,
                                        uint32_t index) {
    if (index == kNoLight || lightCount(lights) == 0) return 0.0f;
    if (lights.built) switch (kind) {
        case LightSamplerKind::Power: return discretePmf(lights.power, index);
        case LightSamplerKind::Bvh: return lightBvhPmf(lights, ctx, index);
        case LightSamplerKind::Colliders: return colliderLightPmf(lights, ctx.p, index);
        case LightSamplerKind::Uniform: break;
        }
    return 1.0f / float(lightCount(lights));
}

/// Picks a light for the shading point `ctx` with one uniform number: its index and the probability
/// of picking it (kNoLight and 0 where there is nothing to pick).
URBIS_HD inline uint32_t selectLight(const LightsView& lights, LightSamplerKind kind, const LightSampleContext& ctx, float u,
                                     float& pmf) {
    const uint32_t n = lightCount(lights);
    pmf = 0.0f;
    if (n == 0) return kNoLight;
    if (lights.built) switch (kind) {
        case LightSamplerKind::Power: return sampleDiscrete(lights.power, u, pmf);
        case LightSamplerKind::Bvh: return sampleLightBvh(lights, ctx, u, pmf);
        case LightSamplerKind::Colliders: return sampleColliderLight(lights, ctx.p, u, pmf);
        case LightSamplerKind::Uniform: break;
        }
    pmf = 1.0f / float(n);
    return uint32_t(fminf(u * float(n), float(n - 1)));
}

/// The light of the emitting triangle `triangle` (index into SceneView::triangles), or kNoLight if
/// its emission is not light-sampled: a binary search of LightsView::emitterTriangles.
URBIS_HD inline uint32_t lightOfTriangle(const LightsView& lights, uint32_t triangle) {
    uint32_t lo = 0, hi = lights.emitterCount;
    while (lo < hi) {
        const uint32_t mid = (lo + hi) / 2;
        if (lights.emitterTriangles[mid].triangle < triangle) lo = mid + 1;
        else hi = mid;
    }
    return lo < lights.emitterCount && lights.emitterTriangles[lo].triangle == triangle ? lights.emitterTriangles[lo].light
                                                                                          : kNoLight;
}

} // namespace urbis
