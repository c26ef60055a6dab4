// Photon tracing (host+device): a photon path from a light through every primitive kind (traceScene
// and SurfaceHit), scattered by the same BSDF sampling as the path tracer, with Russian roulette,
// handing its stores to a sink: the photon map's slots or the photon buffers' splats. The direct light
// of light-sampled lights is the camera pass's next-event estimation, so a photon is stored only at
// non-specular hits after its first bounce. docs/photons.md § Tracing.
#pragma once

#include "geometry/scene_intersect.h"
#include "integrators/bsdf.h"
#include "integrators/path_tracer.h"
#include "integrators/photon_emit.h"
#include "scene/render_settings.h"

namespace urbis {

/// Salt of the photons' random numbers, apart from the camera samples' streams.
inline constexpr uint32_t kPhotonSeedSalt = 0x50484f54u;

/// The random numbers of photon `index` of pass `pass`.
URBIS_HD inline SampleStream photonStream(const RenderSettings& settings, uint32_t pass, uint32_t index) {
    return SampleStream{settings.seed ^ kPhotonSeedSalt, index, pass};
}

/// Traces photon `index` of the pass scene.photons.pass, handing every store to
/// `sink(hit, wi, power, storeIndex)` (storeIndex < settings.maxDepth). Returns the rays traced.
template <typename Sink>
URBIS_HD inline uint32_t tracePhoton(const SceneView& scene, const RenderSettings& settings, uint32_t index, Sink& sink) {
    SampleStream rng = photonStream(settings, scene.photons.pass, index);
    EmittedPhoton photon;
    if (!emitPhoton(scene, settings.photonsPerPass, rng, photon)) return 0;
    Ray ray = photon.ray;
    Vec3f throughput{1, 1, 1};
    uint32_t rays = 0, stores = 0;
    for (uint32_t depth = 0; depth < settings.maxDepth; ++depth) {
        const SurfaceHit hit = traceScene(scene, ray, false);
        ++rays;
        if (!hit.valid()) break;
        const Material& material = scene.materials[hit.material];
        const Vec3f dir = normalize(ray.dir);
        if (!isSpecular(material) && (depth > 0 || photon.depositFirst)) sink(hit, -dir, photon.power * throughput, stores++);
        BsdfSample bsdf;
        const float u0 = material.kind == MaterialKind::Lambertian ? 0.0f : rng.draw();
        const float u1 = rng.draw(), u2 = rng.draw();
        if (!sampleBsdf(material, -dir, hit.normal, u0, u1, u2, bsdf)) break;
        throughput *= bsdf.weight;
        if (depth + 1 >= settings.rrDepth) {
            const float survival = fminf(maxComponent(throughput), settings.rrSurvival);
            if (!(rng.draw() < survival)) break;
            throughput *= 1.0f / survival;
        }
        const Vec3f offset = rayOriginOffset(hit.position, hit.normal);
        ray = Ray{dot(bsdf.dir, hit.normal) > 0.0f ? hit.position + offset : hit.position - offset, bsdf.dir};
    }
    return rays;
}

} // namespace urbis
