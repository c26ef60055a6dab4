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
    // Photon integrators (docs/photons.md): one photon pass per sample index.
    uint32_t photonsPerPass = 65536;
    float photonRadius = 1.0f;        ///< metres: the photon map's gather radius at the first pass
    float photonAlpha = 0.7f;         ///< share of photons each pass keeps when the radius shrinks (Knaus and Zwicker 2011)
    float photonTexel = 0.5f;         ///< metres: side of a photon buffer's texel at level 0
    float photonLevelDistance = 40.0f;  ///< metres: blocks nearer than this get level 0; each doubling one level more, up to 4
};

} // namespace urbis
