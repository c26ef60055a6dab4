// The unidirectional path tracer: diffuse, glossy, mirror and glass surfaces, emitters found by
// BSDF sampling, sun by next-event estimation (and by specular bounces), sky by BSDF sampling,
// Russian roulette. Host+device; runs once per pixel sample.
#pragma once

#include "integrators/bsdf.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "geometry/scene_intersect.h"

namespace urbis {

/// Radiance of one camera sample and how many rays it traced.
struct PathSample {
    Vec3f radiance;
    uint32_t rays = 0;
};

/// Offset from a surface point along its facing normal, scaled with the point's magnitude so that
/// new rays clear the surface at city coordinates (thousands of metres) in float precision.
URBIS_HD inline Vec3f offsetRayOrigin(Vec3f p, Vec3f facingNormal) {
    const float scale = fusedMulAdd(4e-6f, maxComponent(Vec3f{fabsf(p.x), fabsf(p.y), fabsf(p.z)}), 1e-4f);
    return fusedMulAdd(facingNormal, scale, p);
}

/// Traces the path of sample `sampleIndex` through pixel (px, py); pure function of its arguments.
URBIS_HD inline PathSample tracePath(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                     uint32_t px, uint32_t py, uint32_t sampleIndex) {
    SampleStream rng{settings.seed, py * settings.width + px, sampleIndex};
    float jx = rng.draw(), jy = rng.draw();
    Ray ray = camera.generateRay(approxDivide(float(px) + jx, float(settings.width)),
                                 approxDivide(float(py) + jy, float(settings.height)));
    PathSample out;
    Vec3f throughput{1, 1, 1};
    bool specularBounce = false;   // the camera ray does not show the sun's disk
    // Each ray of the path, the sun's shadow rays included, is traced at the one call of traceScene
    // below, so that the GPU kernel holds one copy of the traversal (docs/gpu_notes.md): a pending
    // shadow ray is traced first, then the path goes on (or ends, if `pathEnds`).
    Ray shadow;
    Vec3f sunlight;                // what the pending shadow ray adds if nothing blocks it
    bool shadowPending = false, pathEnds = false;
    for (uint32_t depth = 0;;) {
        const SurfaceHit hit = traceScene(scene, shadowPending ? shadow : ray, shadowPending);
        ++out.rays;
        if (shadowPending) {
            if (!hit.valid()) out.radiance += sunlight;
            shadowPending = false;
            if (pathEnds) break;
            continue;
        }
        if (!hit.valid()) {
            out.radiance = fusedMulAdd(throughput, scene.sky.radiance(ray.dir), out.radiance);
            // Light sampling cannot reach the disk through a mirror or glass: count it here.
            if (specularBounce && scene.sun.contains(approxNormalize(ray.dir)))
                out.radiance = fusedMulAdd(throughput, scene.sun.radiance, out.radiance);
            break;
        }
        Vec3f normal = hit.normal;
        const Material& material = scene.materials[hit.material];
        // No emitter is light-sampled yet, so every hit counts its emission in full.
        out.radiance = fusedMulAdd(throughput, material.emission, out.radiance);
        Vec3f wo = approxNormalize(-ray.dir);
        const Vec3f position = fusedMulAdd(ray.dir, hit.t, ray.origin);

        // Next-event estimation towards the sun's disk; the sky lookup never includes the disk.
        float u1 = rng.draw(), u2 = rng.draw();
        if (scene.sun.enabled() && !isSpecular(material)) {
            Vec3f toSun = scene.sun.sampleDirection(u1, u2);
            Vec3f fCos = evalBsdfCos(material, wo, toSun, normal);
            if (maxComponent(fCos) > 0.0f) {
                shadow = Ray{offsetRayOrigin(position, normal), toSun};
                sunlight = throughput * fCos * scene.sun.radiance * approxDivide(1.0f, scene.sun.pdf());
                shadowPending = true;
            }
        }
        // The path goes on unless it is deep enough, is absorbed or loses the Russian roulette.
        BsdfSample bsdf;
        bool goesOn = depth + 1 < settings.maxDepth;
        if (goesOn) {
            float u3 = rng.draw(), u4 = rng.draw();
            float u5 = material.kind == MaterialKind::Lambertian ? 0.0f : rng.draw();
            goesOn = sampleBsdf(material, wo, normal, u5, u3, u4, bsdf);
        }
        if (goesOn) {
            throughput *= bsdf.weight;
            specularBounce = bsdf.specular;
            if (depth + 1 >= settings.rrDepth) {
                float survival = fminf(maxComponent(throughput), settings.rrSurvival);
                goesOn = rng.draw() < survival;
                throughput *= approxDivide(1.0f, survival);
            }
        }
        if (!goesOn) {
            pathEnds = true;
            if (shadowPending) continue;
            break;
        }
        ray = Ray{offsetRayOrigin(position, fusedDot(bsdf.dir, normal) > 0.0f ? normal : -normal), bsdf.dir};
        ++depth;
    }
    return out;
}

} // namespace urbis
