// The camera pass of the photon integrators (host+device): the camera ray and its specular chain
// (mirrors, glass) to the first non-specular hit, direct light there by next-event estimation with
// the scene's light sampler, indirect light from the photons: a hash-grid gather (the photon map) or
// one look-up of the block's photon buffer (Argudo et al.). docs/photons.md § The camera pass.
#pragma once

#include "integrators/camera_sample.h"
#include "integrators/path_tracer.h"
#include "integrators/photon_buffers.h"
#include "integrators/photon_grid.h"

namespace urbis {

/// The end of a camera sample's specular chain.
struct CameraChainEnd {
    SurfaceHit hit;          ///< the first non-specular hit; invalid where the chain escaped or ended
    Vec3f throughput{1, 1, 1};
    Vec3f wo;                ///< unit, from the hit back along the chain
};

/// A camera sample's chain: its random numbers (drawn up to the chain's end), what it saw on its way
/// (emitters, the sky) and where it ended.
struct CameraChain {
    SampleStream rng;
    PathSample out;
    CameraChainEnd end;
};

/// Follows the camera ray of sample `sampleIndex` through pixel (px, py) through specular bounces to
/// its first non-specular hit. The flag pass of the photon buffers and the camera pass call it alike,
/// so both find the same hit.
URBIS_HD inline CameraChain followCameraChain(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                              uint32_t px, uint32_t py, uint32_t sampleIndex) {
    CameraChain chain{pixelSampleStream(settings, px, py, sampleIndex), {}, {}};
    SampleStream& rng = chain.rng;
    PathSample& out = chain.out;
    CameraChainEnd& end = chain.end;
    Ray ray = cameraSampleRay(camera, settings, px, py, rng);
    for (uint32_t depth = 0; depth < settings.maxDepth; ++depth) {
        const SurfaceHit hit = traceScene(scene, ray, false);
        ++out.rays;
        const Vec3f dir = normalize(ray.dir);
        if (!hit.valid()) {
            // A camera ray or one after specular bounces: what it sees counts in full, as no light
            // sample could find it from the chain (the sun's disk only after a bounce).
            addEscapedEmission(scene, settings, ray, dir, depth, BounceInfo{}, end.throughput, out.radiance);
            return chain;
        }
        applyAerialPerspective(scene, ray, hit.t, end.throughput, out.radiance);
        const Material& material = scene.materials[hit.material];
        out.radiance += end.throughput * foundEmission(scene, settings, hit, material, ray, dir, BounceInfo{});
        if (!isSpecular(material)) {
            end.hit = hit;
            end.wo = -dir;
            return chain;
        }
        BsdfSample bsdf;
        sampleBsdf(material, -dir, hit.normal, rng.draw(), 0.0f, 0.0f, bsdf);
        end.throughput *= bsdf.weight;
        const Vec3f offset = rayOriginOffset(hit.position, hit.normal);
        ray = Ray{dot(bsdf.dir, hit.normal) > 0.0f ? hit.position + offset : hit.position - offset, bsdf.dir};
    }
    return chain;
}

/// Indirect light towards `wo` (unit) at a camera chain's non-specular hit from the photons: the photon
/// map's gather (`integrator` PhotonMap), or one look-up of the block's photon buffer, irradiance times
/// albedo / pi (PhotonBuffers). The lighting pass of Argudo et al.
URBIS_HD inline Vec3f photonIndirect(const SceneView& scene, IntegratorKind integrator, const SurfaceHit& hit, Vec3f wo) {
    const Material& material = scene.materials[hit.material];
    if (integrator == IntegratorKind::PhotonMap) return gatherPhotons(scene.photons.grid, material, hit.position, hit.normal, wo);
    if (!bufferedSurface(hit)) return {};
    return material.albedo * (1.0f / kPi) *
           bufferIrradiance(scene.photons.buffers, hit.position, hit.normal, hit.object, scene.photons.pass);
}

/// Radiance of sample `sampleIndex` through pixel (px, py) by a photon integrator: the chain's
/// emission, next-event estimation at its end (at least one light sample: photons carry no direct
/// light of light-sampled lights) and the photons' indirect light there.
URBIS_HD inline PathSample photonCameraSample(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                              uint32_t px, uint32_t py, uint32_t sampleIndex) {
    CameraChain chain = followCameraChain(scene, camera, settings, px, py, sampleIndex);
    PathSample& out = chain.out;
    const CameraChainEnd& end = chain.end;
    if (!end.hit.valid()) return out;
    const SurfaceHit& hit = end.hit;
    RenderSettings direct = settings;
    direct.lightSamples = settings.lightSamples > 0 ? settings.lightSamples : 1;
    PathVertex vertex;
    vertex.origin = offsetRayOrigin(hit.position, hit.normal);
    vertex.normal = hit.normal;
    vertex.wo = end.wo;
    vertex.throughput = end.throughput;
    vertex.material = hit.material;
    vertex.bsdfStrategy = false;   // no BSDF sample follows: light samples count in full
    for (uint32_t i = 0; i < direct.lightSamples; ++i) {
        Ray shadow;
        Vec3f contribution;
        CloudOctaves octaves;
        if (!sampleShadowRay(scene, direct, vertex, chain.rng, shadow, contribution, octaves)) continue;
        ++out.rays;
        if (!traceScene(scene, shadow, true).valid())
            out.radiance += contribution * cloudTransmittance(scene, shadow, octaves, chain.rng);
    }
    out.radiance += end.throughput * photonIndirect(scene, settings.integrator, hit, end.wo);
    return out;
}

/// The block whose buffers the camera sample's chain ends on (the flag pass), or kNoBlock.
URBIS_HD inline uint32_t cameraSampleBlock(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                           uint32_t px, uint32_t py, uint32_t sampleIndex) {
    const SurfaceHit hit = followCameraChain(scene, camera, settings, px, py, sampleIndex).end.hit;
    return hit.valid() ? photonBlockOf(scene.photons.buffers, hit.position, hit.object) : kNoBlock;
}

} // namespace urbis
