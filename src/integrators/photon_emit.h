// Photon emission (host+device): a photon leaves a light of the scene's list, picked in proportion to
// its power by the light sampler (lights/light_sampler.h, LightSamplerKind::Power), or the sky when the
// sky is not in the list (by day: docs/lights.md), with the flux that makes the photons of a pass an
// unbiased estimate of the emitted light; each light kind sends its photon (its emitPhoton).
// docs/photons.md § Emission.
#pragma once

#include "lights/light.h"
#include "lights/light_sampler.h"
#include "math/rng.h"

namespace urbis {

/// Emits photon `index` of a pass of `count` from the scene's lights with the numbers of `rng`.
/// Returns false when it carries nothing (an unlit window, a lamp's dark side): it still counts as emitted.
URBIS_HD inline bool emitPhoton(const SceneView& scene, uint32_t count, SampleStream& rng, EmittedPhoton& out) {
    const PhotonsView& photons = scene.photons;
    const float u = rng.draw(), u1 = rng.draw(), u2 = rng.draw(), u3 = rng.draw(), u4 = rng.draw();
    const float perPhoton = 1.0f / float(count);
    if (u < photons.skyPmf) {
        out = skyPhoton(scene, u1, u2, u3, u4);
        out.power *= perPhoton / photons.skyPmf;
        out.depositFirst = true;
        return maxComponent(out.power) > 0.0f;
    }
    float pmf;
    const float uList = (u - photons.skyPmf) / (1.0f - photons.skyPmf);
    const uint32_t index = selectLight(scene, LightSamplerKind::Power, LightSampleContext{}, fminf(uList, 0x1.fffffep-1f), pmf);
    if (!(pmf > 0.0f)) return false;
    const float scale = perPhoton / ((1.0f - photons.skyPmf) * pmf);
    const LightRecord light = lightRecord(scene, index);
    out.depositFirst = false;
    const PhotonNumbers numbers{u1, u2, u3, u4};
    if (!dispatchLight(light.kind, [&](auto kind) {
            return decltype(kind)::Light::emitPhoton(scene, light, numbers, rng, scale, out);
        }))
        return false;
    return maxComponent(out.power) > 0.0f;
}

} // namespace urbis
