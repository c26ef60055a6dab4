// The light sampler (host+device): picks one light of the scene's list for next-event estimation
// and says with what probability it picks a given one, for MIS.
#pragma once

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

/// Probability that selectLight picks light `index` (kNoLight: 0).
URBIS_HD inline float lightSelectionPmf(const LightsView& lights, LightSamplerKind kind, uint32_t index) {
    if (index == kNoLight || lightCount(lights) == 0) return 0.0f;
    switch (kind) {
    case LightSamplerKind::Power:
        if (lights.built) return discretePmf(lights.power, index);
        break;  // no table: as Uniform
    case LightSamplerKind::Uniform:
        break;
    }
    return 1.0f / float(lightCount(lights));
}

/// Picks a light with one uniform number: its index and the probability of picking it (kNoLight
/// and 0 from an empty list).
URBIS_HD inline uint32_t selectLight(const LightsView& lights, LightSamplerKind kind, float u, float& pmf) {
    const uint32_t n = lightCount(lights);
    pmf = 0.0f;
    if (n == 0) return kNoLight;
    if (kind == LightSamplerKind::Power && lights.built) return sampleDiscrete(lights.power, u, pmf);
    pmf = 1.0f / float(n);
    return uint32_t(fminf(u * float(n), float(n - 1)));
}

} // namespace urbis
