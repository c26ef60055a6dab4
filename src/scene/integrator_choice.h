// The closed sets a render chooses from (host+device enums) with the names scene files and options
// give them: which integrator runs, and how it picks a light for next-event estimation.
#pragma once

#include "base/choice.h"

#include <cstdint>

namespace urbis {

/// Integrators both backends drive through integrateSample (integrators/integrator.h).
enum class IntegratorKind : uint32_t {
    Path,  ///< unidirectional path tracing with MIS (integrators/path_tracer.h)
    PhotonBuffers,  ///< indirect light from per-block photon buffers (Argudo et al.; integrators/photon_camera.h)
    PhotonMap,      ///< indirect light from a hash-grid photon map with progressive radius reduction (the reference)
};
inline constexpr Choice<IntegratorKind> kIntegratorKinds[] = {
    {"path", IntegratorKind::Path}, {"photon-buffers", IntegratorKind::PhotonBuffers}, {"photon-map", IntegratorKind::PhotonMap}};

/// How the light sampler picks one light of the scene's list (lights/light_sampler.h).
enum class LightSamplerKind : uint32_t {
    Uniform,  ///< every light of the list alike
    Power,    ///< in proportion to each light's power (LightRecord::power)
    Bvh,      ///< by the light BVH at the shading point (Conty Estevez and Kulla 2018; lights/light_bvh.h)
    Colliders,  ///< the thesis's colliders: uniformly among the lights near the point (lights/collider_lights.h)
};
inline constexpr Choice<LightSamplerKind> kLightSamplers[] = {{"uniform", LightSamplerKind::Uniform},
                                                              {"power", LightSamplerKind::Power},
                                                              {"bvh", LightSamplerKind::Bvh},
                                                              {"colliders", LightSamplerKind::Colliders}};

} // namespace urbis
