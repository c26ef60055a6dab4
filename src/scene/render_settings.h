// Per-frame integrator settings (host+device POD).
#pragma once

#include "scene/integrator_choice.h"

#include <cstdint>

namespace urbis {

struct RenderSettings {
    uint32_t width = 1280, height = 720;
    uint32_t spp = 16;            ///< samples per pixel
    uint32_t seed = 1;
    uint32_t maxDepth = 8;        ///< path vertices after the camera
    uint32_t rrDepth = 3;         ///< Russian roulette starts at this depth
    float rrSurvival = 0.95f;     ///< upper bound of the survival probability
    IntegratorKind integrator = IntegratorKind::Path;
    LightSamplerKind lightSampler = LightSamplerKind::Power;
    uint32_t lightSamples = 1;    ///< next-event estimates per path vertex; 0: BSDF sampling alone
};

} // namespace urbis
