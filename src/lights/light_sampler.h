// The light sampler (host+device): picks one light of the scene's list for next-event estimation at
// a shading point and says with what probability it picks a given one there, for MIS.
#pragma once

#include "lights/collider_lights.h"
#include "lights/light_bvh.h"
#include "math/piecewise_constant.h"
#include "scene/integrator_choice.h"
#include "scene/scene_view.h"

namespace urbis {

/// Lights in the list; a list not built stands for {sun}.
URBIS_HD inline uint32_t lightCount(const SceneView& scene) { return scene.lights.built ? scene.lightRecords.size : 1u; }

/// The record of light `index` of the list.
URBIS_HD inline LightRecord lightRecord(const SceneView& scene, uint32_t index) {
    if (scene.lights.built) return scene.lightRecords[index];
    return LightRecord{kLightKindOf<SunLight>, 0, 0.0f};
}

/// The power-weighted choice's table over the list's records.
URBIS_HD inline PiecewiseConstant1DView lightPowerTable(const SceneView& scene) {
    return piecewiseConstant1DView(scene.lightPower.data, scene.lightPower.size, scene.lights.powerIntegral);
}

/// Probability that selectLight(ctx) picks light `index` (kNoLight: 0). The light BVH and the
/// colliders need built lights; without them they fall back to Uniform, as Power does.
URBIS_HD inline float lightSelectionPmf(const SceneView& scene, LightSamplerKind kind, const LightSampleContext& ctx,
                                        uint32_t index) {
    if (index == kNoLight || lightCount(scene) == 0) return 0.0f;
    if (scene.lights.built) switch (kind) {
        case LightSamplerKind::Power: return discretePmf(lightPowerTable(scene), index);
        case LightSamplerKind::Bvh: return lightBvhPmf(scene, ctx, index);
        case LightSamplerKind::Colliders: return colliderLightPmf(scene, ctx.p, index);
        case LightSamplerKind::Uniform: break;
        }
    return 1.0f / float(lightCount(scene));
}

/// Picks a light for the shading point `ctx` with one uniform number: its index and the probability
/// of picking it (kNoLight and 0 where there is nothing to pick).
URBIS_HD inline uint32_t selectLight(const SceneView& scene, LightSamplerKind kind, const LightSampleContext& ctx, float u,
                                     float& pmf) {
    const uint32_t n = lightCount(scene);
    pmf = 0.0f;
    if (n == 0) return kNoLight;
    if (scene.lights.built) switch (kind) {
        case LightSamplerKind::Power: return sampleDiscrete(lightPowerTable(scene), u, pmf);
        case LightSamplerKind::Bvh: return sampleLightBvh(scene, ctx, u, pmf);
        case LightSamplerKind::Colliders: return sampleColliderLight(scene, ctx.p, u, pmf);
        case LightSamplerKind::Uniform: break;
        }
    pmf = 1.0f / float(n);
    return uint32_t(fminf(u * float(n), float(n - 1)));
}

} // namespace urbis
