// The unidirectional path tracer: Lambertian surfaces, sun by next-event estimation,
// sky by BSDF sampling, Russian roulette. Host+device; runs once per pixel sample.
#pragma once

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
    float scale = 1e-4f + 4e-6f * maxComponent(Vec3f{fabsf(p.x), fabsf(p.y), fabsf(p.z)});
    return p + facingNormal * scale;
}

/// Traces the path of sample `sampleIndex` through pixel (px, py); pure function of its arguments.
URBIS_HD inline PathSample tracePath(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                     uint32_t px, uint32_t py, uint32_t sampleIndex) {
    SampleStream rng{settings.seed, py * settings.width + px, sampleIndex};
    float jx = rng.draw(), jy = rng.draw();
    Ray ray = camera.generateRay((float(px) + jx) / float(settings.width), (float(py) + jy) / float(settings.height));
    PathSample out;
    Vec3f throughput{1, 1, 1};
    for (uint32_t depth = 0;; ++depth) {
        SurfaceHit hit = intersectScene(scene, ray);
        ++out.rays;
        if (!hit.valid()) {
            out.radiance += throughput * scene.sky.radiance(ray.dir);
            break;
        }
        Vec3f normal = hit.normal;
        Vec3f albedo = scene.materials[hit.material].albedo;
        Vec3f origin = offsetRayOrigin(ray.origin + ray.dir * hit.t, normal);

        // Next-event estimation towards the sun's disk; the sky lookup never includes the disk.
        float u1 = rng.draw(), u2 = rng.draw();
        if (scene.sun.enabled()) {
            Vec3f toSun = scene.sun.sampleDirection(u1, u2);
            float cosine = dot(toSun, normal);
            if (cosine > 0.0f) {
                Ray shadow{origin, toSun};
                ++out.rays;
                if (!occludedScene(scene, shadow))
                    out.radiance += throughput * albedo * scene.sun.radiance * (cosine / (kPi * scene.sun.pdf()));
            }
        }
        if (depth + 1 >= settings.maxDepth) break;

        // Cosine sampling makes the Lambertian weight f * cos / pdf equal to the albedo.
        float u3 = rng.draw(), u4 = rng.draw();
        throughput *= albedo;
        if (depth + 1 >= settings.rrDepth) {
            float survival = fminf(maxComponent(throughput), settings.rrSurvival);
            if (rng.draw() >= survival) break;
            throughput *= 1.0f / survival;
        }
        ray = Ray{origin, Frame::fromZ(normal).toWorld(sampleCosineHemisphere(u3, u4))};
    }
    return out;
}

} // namespace urbis
