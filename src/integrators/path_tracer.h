// The unidirectional path tracer: diffuse, glossy, mirror, glass and water surfaces (with absorption
// below the water, integrators/water.h); next-event estimation of the scene's lights combined with
// BSDF sampling by the power heuristic (integrators/path_lights.h); scattering in clouds; Russian
// roulette. Host+device; runs once per pixel sample. tracePath's loop traces one ray per iteration
// and hands what it met to one named step; the steps share the path's state (PathState).
#pragma once

#include "integrators/camera_sample.h"
#include "integrators/path_lights.h"
#include "integrators/water.h"
#include "media/aerial_perspective.h"
#include "media/planet_atmosphere.h"

namespace urbis {

/// Radiance of one camera sample and how many rays it traced.
struct PathSample {
    Vec3f radiance;
    uint32_t rays = 0;
};

/// Russian roulette for the path of `depth` vertices going on with `throughput` (divided by the
/// survival probability where it survives); true unless it is lost.
URBIS_HD inline bool survivesRoulette(uint32_t depth, const RenderSettings& settings, Vec3f& throughput, SampleStream& rng) {
    if (depth + 1 < settings.rrDepth) return true;
    const float survival = fminf(maxComponent(throughput), settings.rrSurvival);
    throughput *= 1.0f / survival;
    return rng.draw() < survival;
}

/// What tracePath carries from one ray to the next.
struct PathState {
    SampleStream rng;
    Ray pathRay{};                  ///< the path's own next ray, traced once the vertex's light samples are
    Ray ray{};                      ///< the ray traced now: the path's or a shadow ray
    PathSample out{};
    Vec3f throughput{1, 1, 1};
    BounceInfo bounce{};            ///< how pathRay was drawn
    PathVertex vertex{};            ///< the last scattering vertex, whose light samples are pending
    Vec3f shadowContribution{};     ///< what the shadow ray in flight adds if nothing blocks it
    bool tracingShadow = false, pathEnds = false;
    uint32_t lightSamplesLeft = 0;
    uint32_t depth = 0;             ///< scattering vertices so far
    WaterPath water{};              ///< the absorption of the water the path is in
};

/// A shadow ray came back: what it carries arrives if nothing blocked it, times the clouds'
/// transmittance weighed by `octaves`.
URBIS_HD inline void addUnblockedShadow(const SceneView& scene, PathState& s, const CloudOctaves& octaves,
                                        const SurfaceHit& hit) {
    if (!hit.valid()) s.out.radiance += s.shadowContribution * cloudTransmittance(scene, s.ray, octaves, s.rng);
}

/// A droplet of a cloud before any surface, at ray parameter `tCloud`: the path scatters there by the
/// phase function.
URBIS_HD inline void scatterInCloud(const SceneView& scene, const RenderSettings& settings, PathState& s, float tCloud) {
    applySegmentMedium(scene, s.ray, tCloud, s.throughput, s.out.radiance);
    const CloudLayer& layer = scene.cloudLayers[0];
    const Vec3f dir = normalize(s.ray.dir);
    s.throughput *= layer.albedo;
    s.vertex = PathVertex{s.ray.origin + s.ray.dir * tCloud, Vec3f{}, -dir, s.throughput, 0, s.depth + 1 < settings.maxDepth, true};
    s.lightSamplesLeft = settings.lightSamples;
    bool goesOn = s.vertex.bsdfStrategy;
    if (goesOn) {
        const CloudPhase phase = cloudPhase(layer);
        const float uLobe = s.rng.draw(), u1 = s.rng.draw(), u2 = s.rng.draw();
        const Vec3f next = sampleCloudPhase(phase, dir, uLobe, u1, u2);
        s.bounce = BounceInfo{cloudPhaseValue(phase, dot(dir, next)), false, false, lightContext(s.vertex)};
        goesOn = survivesRoulette(s.depth, settings, s.throughput, s.rng);
        s.pathRay = Ray{s.vertex.origin, next};
    }
    s.pathEnds = !goesOn;
    s.depth += goesOn;
}

/// The path's ray met nothing: the infinite lights and the stars (addEscapedEmission); the path ends.
URBIS_HD inline void escape(const SceneView& scene, const RenderSettings& settings, PathState& s) {
    s.throughput *= s.water.transmittance(3.0e38f);   // below a water's surface nothing comes from afar
    const Vec3f dir = normalize(s.ray.dir);
    addEscapedEmission(scene, settings, s.ray, dir, s.depth, s.bounce, s.throughput, s.out.radiance);
    s.pathEnds = true;
}

/// The path's ray met a surface at `hit`: what it emits there (foundEmission), the vertex whose light
/// samples come next, and the BSDF sample that the path goes on with unless it is deep enough, is
/// absorbed or loses the Russian roulette.
URBIS_HD inline void scatterAtSurface(const SceneView& scene, const RenderSettings& settings, PathState& s,
                                      const SurfaceHit& hit) {
    applySegmentMedium(scene, s.ray, hit.t, s.throughput, s.out.radiance);
    s.throughput *= s.water.transmittance(hit.t * length(s.ray.dir));
    const Material& material = scene.materials[hit.material];
    const Vec3f dir = normalize(s.ray.dir);
    s.out.radiance += s.throughput * foundEmission(scene, settings, hit, material, s.ray, dir, s.bounce);
    const Vec3f offset = rayOriginOffset(hit.position, hit.normal);
    PathVertex& vertex = s.vertex;
    vertex.origin = hit.position + offset;
    vertex.normal = hit.normal;
    vertex.wo = -dir;
    vertex.throughput = s.throughput;
    vertex.material = hit.material;
    vertex.inCloud = false;
    const bool scatters = !isSpecular(material);
    BsdfSample bsdf;
    bool goesOn = s.depth + 1 < settings.maxDepth;
    // Whether BSDF sampling is a strategy here does not depend on how its sample turns out
    // (absorbed, below the surface, lost to Russian roulette): the light samples' weights must not.
    vertex.bsdfStrategy = goesOn;
    float nextTmin = 0.0f;          // past a water's skipBelow for a ray refracted into it
    if (goesOn) {
        float u3 = s.rng.draw(), u4 = s.rng.draw();
        float u5 = material.kind == MaterialKind::Lambertian ? 0.0f : s.rng.draw();
        const bool isWater = material.kind == MaterialKind::Water;
        const Vec3f n = isWater ? waterShadingNormal(material, hit.position, hit.normal, vertex.wo) : vertex.normal;
        goesOn = sampleBsdf(material, vertex.wo, n, u5, u3, u4, bsdf);
        nextTmin = goesOn && isWater ? s.water.scattered(material, n, hit.normal, bsdf) : 0.0f;
    }
    if (goesOn) {
        s.throughput *= bsdf.weight;
        s.bounce = bounceAfter(s.bounce, vertex, material, bsdf);
        goesOn = survivesRoulette(s.depth, settings, s.throughput, s.rng);
    }
    s.lightSamplesLeft = scatters ? settings.lightSamples : 0;
    s.pathEnds = !goesOn;
    if (goesOn) {
        s.pathRay = Ray{dot(bsdf.dir, hit.normal) > 0.0f ? vertex.origin : hit.position - offset, bsdf.dir, nextTmin};
        ++s.depth;
    }
}

/// Chooses the next ray: the vertex's pending light samples first (a shadow ray's clouds weighed by
/// `octaves`), then the path's own. False when the path is done.
URBIS_HD inline bool nextRay(const SceneView& scene, const RenderSettings& settings, PathState& s, CloudOctaves& octaves) {
    s.tracingShadow = false;
    while (s.lightSamplesLeft > 0 && !s.tracingShadow) {
        --s.lightSamplesLeft;
        s.tracingShadow = sampleShadowRay(scene, settings, s.vertex, s.rng, s.ray, s.shadowContribution, octaves);
    }
    if (s.tracingShadow) return true;
    if (s.pathEnds) return false;
    s.ray = s.pathRay;
    return true;
}

/// Traces the path of sample `sampleIndex` through pixel (px, py); pure function of its arguments.
/// Every ray, the path's and the light samples' shadow rays, is traced at the one call of
/// traceScene in the loop, so that the GPU kernel holds one copy of the traversal: after a vertex is
/// shaded, its settings.lightSamples shadow rays come next, one per iteration, then the path's
/// next ray. A medium step joins the same way, as one more kind of next ray.
URBIS_HD inline PathSample tracePath(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                     uint32_t px, uint32_t py, uint32_t sampleIndex) {
    PathState s{pixelSampleStream(settings, px, py, sampleIndex)};
    s.pathRay = cameraSampleRay(camera, settings, px, py, s.rng);
    s.ray = s.pathRay;
    // Apart from PathState: its arrays are indexed at run time, which would keep the whole state in
    // the GPU's local memory rather than in registers.
    CloudOctaves shadowOctaves;
    do {
        const SurfaceHit hit = traceScene(scene, s.ray, s.tracingShadow);
        ++s.out.rays;
        if (s.tracingShadow) addUnblockedShadow(scene, s, shadowOctaves, hit);
        else if (float tCloud; cloudCollision(scene, s.ray, hit.valid() ? hit.t : s.ray.tmax, s.rng, tCloud))
            scatterInCloud(scene, settings, s, tCloud);
        else if (!hit.valid()) escape(scene, settings, s);
        else scatterAtSurface(scene, settings, s, hit);
    } while (nextRay(scene, settings, s, shadowOctaves));
    return s.out;
}

} // namespace urbis
