// The unidirectional path tracer: diffuse, glossy, mirror, glass and water surfaces (with absorption
// below the water, integrators/water.h); next-event estimation of the scene's lights (sun, sky,
// emitting surfaces) combined with BSDF sampling by the power heuristic (Veach 1997, chapter 9);
// Russian roulette. Host+device; runs once per pixel sample.
#pragma once

#include "geometry/scene_intersect.h"
#include "integrators/bsdf.h"
#include "integrators/camera_sample.h"
#include "integrators/water.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights/mis.h"
#include "lights/star_field.h"
#include "media/planet_atmosphere.h"
#include "media/aerial_perspective.h"
#include "media/cloud_scattering.h"
#include "scene/render_settings.h"

namespace urbis {

/// Radiance of one camera sample and how many rays it traced.
struct PathSample {
    Vec3f radiance;
    uint32_t rays = 0;
};

/// Offset from a surface point to clear it along its facing normal, scaled with the point's magnitude
/// so that new rays clear the surface at city coordinates (thousands of metres) in float precision.
URBIS_HD inline Vec3f rayOriginOffset(Vec3f p, Vec3f facingNormal) {
    return facingNormal * (4e-6f * maxComponent(Vec3f{fabsf(p.x), fabsf(p.y), fabsf(p.z)}) + 1e-4f);
}

/// The origin of rays that leave the surface point `p` on the side of `facingNormal`.
URBIS_HD inline Vec3f offsetRayOrigin(Vec3f p, Vec3f facingNormal) { return p + rayOriginOffset(p, facingNormal); }

/// A scattering point of the path, kept while its light samples are traced.
struct PathVertex {
    Vec3f origin;                ///< of its shadow rays, offset from the surface (offsetRayOrigin); lights are sampled from it
    Vec3f normal, wo;            ///< normal: geometric, on the side of wo
    Vec3f throughput;            ///< of the path up to this vertex
    uint32_t material = 0;
    bool bsdfStrategy = false;   ///< whether the path samples its BSDF here (not at maxDepth): MIS counts it
    bool inCloud = false;        ///< a cloud's droplet: its phase function scatters (media/cloud_scattering.h)
};

/// Where the light samples of `vertex` are drawn from, for the light sampler: also where the pick
/// probability of what its BSDF sample finds is asked.
URBIS_HD inline LightSampleContext lightContext(const PathVertex& vertex) { return {vertex.origin, vertex.normal}; }

/// How the BSDF sample that found an emitter was drawn: MIS weighs what it finds.
struct BounceInfo {
    float pdf = 0;        ///< solid angle
    bool countsInFull = true;  ///< camera rays and specular bounces: no light sample can find the same light
    /// The ray left a scattering vertex at `from` with pdf `pdf` and went on only straight through
    /// panes since: a lit room it finds is a window that the vertex's light samples could reach
    /// through the pane (lights/window_light.h), so MIS weighs it though countsInFull is set.
    bool windowPath = false;
    LightSampleContext from{};  ///< the vertex the BSDF sample left: where the pick probability of what it finds is asked
};

/// The BounceInfo of the ray that a BSDF sample `bsdf` of `material` sends on from `vertex`, after a
/// ray of `before`: a pane's straight transmission keeps the window path of the ray it continues.
URBIS_HD inline BounceInfo bounceAfter(const BounceInfo& before, const PathVertex& vertex, const Material& material,
                                       const BsdfSample& bsdf) {
    if (!bsdf.specular) return {bsdf.pdf, false, true, lightContext(vertex)};
    const bool throughPane = material.kind == MaterialKind::Glass && dot(bsdf.dir, vertex.normal) < 0.0f;
    return {before.pdf, true, throughPane && before.windowPath, before.from};
}

/// Whether MIS weighs light samples of `kind` against BSDF sampling. Not the sun's: its disk (about
/// 7e-5 sr) has a light-sampling pdf thousands of times any BSDF's, where the power heuristic would
/// give its light samples a weight of 1 to within (p_bsdf / p_sun)^2. So they count in full and a BSDF
/// sample that finds the disk counts nothing (weights 1 and 0 sum to one as well): no power heuristic
/// per sun sample or per BSDF sample that finds the disk. The moon's disk is as small. Not a lamp's
/// either: a point, which BSDF sampling never finds; its glass, found at a scattering vertex, counts
/// nothing (lights/lamp_light.h).
URBIS_HD inline bool misWeighs(LightKind kind) {
    return kind != LightKind::Sun && kind != LightKind::Moon && kind != LightKind::Point;
}

/// Weight of emission that a BSDF sample of `bounce` found, against `lightSamples` light samples
/// that pick `light` (of kind `kind`) with `selectionPmf` and reach the same point with solid-angle pdf `pdf`.
URBIS_HD inline float bsdfFoundWeight(const BounceInfo& bounce, LightKind kind, uint32_t lightSamples, float selectionPmf,
                                      float pdf) {
    if (bounce.countsInFull || lightSamples == 0 || !(selectionPmf > 0.0f)) return 1.0f;
    if (!misWeighs(kind)) return 0.0f;
    return powerHeuristic(1.0f, bounce.pdf, float(lightSamples), selectionPmf * pdf);
}

/// Weight of one of `lightSamples` light samples of a light of kind `kind`, of solid-angle pdf
/// `lightPdf` (selection included), against the BSDF sample of the same vertex, which would find
/// that direction with `bsdfPdf`.
URBIS_HD inline float lightSampleWeight(LightKind kind, uint32_t lightSamples, float lightPdf, float bsdfPdf) {
    if (!misWeighs(kind)) return 1.0f;
    return powerHeuristic(float(lightSamples), lightPdf, 1.0f, bsdfPdf);
}

/// What a ray of `bounce` with unit direction `dir` finds emitted at `hit` (of `material`), weighed
/// against the light samples that reach it: a lit room (its window's look, lights/window_light.h), a
/// lamp's glass (lights/lamp_light.h), or an emitting material.
URBIS_HD inline Vec3f foundEmission(const SceneView& scene, const RenderSettings& settings, const SurfaceHit& hit,
                                    const Material& material, const Ray& ray, Vec3f dir, const BounceInfo& bounce) {
    const LightsView& lights = scene.lights;
    if (hit.kind == kPrimKindOf<LampRecord> && hit.part == SurfacePart::LampGlass && lights.firstLampLight != kNoLight) {
        float weight = 1.0f;
        if (!bounce.countsInFull)
            weight = bsdfFoundWeight(bounce, LightKind::Point, settings.lightSamples,
                                     lightSelectionPmf(lights, settings.lightSampler, bounce.from, lights.firstLampLight + hit.index), 0.0f);
        return lampGlassRadiance(lights.lampLights[hit.index], -dir) * weight;
    }
    if (!(maxComponent(material.emission) > 0.0f)) return {};
    if (hit.kind == kPrimKindOf<WallRecord>) {
        const WallRecord& wall = scene.walls[hit.index];
        if (hit.material != wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)) return material.emission;
        const Vec3f L = litRoomRadiance(wall, material.emission, ray.origin, dir, hit.uv);
        if (!bounce.windowPath || lights.firstWallLight == kNoLight || settings.lightSamples == 0) return L;
        const uint32_t light = lights.firstWallLight + hit.index;
        const float pdf = lightSelectionPmf(lights, settings.lightSampler, bounce.from, light) *
                          wallWindowsPdf(wall, lightRecord(lights, light).litCells, bounce.from.p, dir);
        return pdf > 0.0f ? L * powerHeuristic(1.0f, bounce.pdf, float(settings.lightSamples), pdf) : L;
    }
    // An emitter found by BSDF sampling: weighed against its light samples where it has any.
    const uint32_t light = hit.kind == kPrimKindOf<Triangle> ? lightOfTriangle(lights, hit.index) : kNoLight;
    if (light == kNoLight || bounce.countsInFull) return material.emission;
    return material.emission * bsdfFoundWeight(bounce, LightKind::EmissiveSurface, settings.lightSamples,
                                               lightSelectionPmf(lights, settings.lightSampler, bounce.from, light),
                                               lightPdf(scene, lightRecord(lights, light), dir, hit.t * length(ray.dir),
                                                        dot(hit.normal, dir)));
}

/// The shadow ray from `origin`, where the light sample was drawn, towards it. Towards a point of a
/// surface it stops short of that point, so that the emitter does not block its own light.
URBIS_HD inline Ray shadowRayTowards(Vec3f origin, const LightSample& ls) {
    if (!(ls.distance < 3.0e38f)) return Ray{origin, ls.dir};
    return Ray{origin, ls.dir, 0.0f, ls.distance * (1.0f - 1e-4f)};
}

/// One light sample from `vertex`: the shadow ray towards the light and what it adds if nothing
/// blocks it, times the clouds' transmittance of `octaves`. Returns false when it adds nothing (then
/// no ray is traced).
URBIS_HD inline bool sampleShadowRay(const SceneView& scene, const RenderSettings& settings, const PathVertex& vertex,
                                     SampleStream& rng, Ray& shadow, Vec3f& contribution, CloudOctaves& octaves) {
    // Numbers are drawn only where they choose something (each draw is a hash): the light where
    // there is more than one, the triangle of a surface or the window of a wall, the point of anything but a lamp.
    const float uLight = lightCount(scene.lights) > 1 ? rng.draw() : 0.0f;
    float pmf;
    const uint32_t index = selectLight(scene.lights, settings.lightSampler, lightContext(vertex), uLight, pmf);
    if (!(pmf > 0.0f)) return false;
    LightSample ls;
    const LightRecord light = lightRecord(scene.lights, index);
    const bool picks = light.kind == LightKind::EmissiveSurface || light.kind == LightKind::Aggregate;
    const float u0 = picks ? rng.draw() : 0.0f;
    const float u1 = light.kind == LightKind::Point ? 0.0f : rng.draw(), u2 = light.kind == LightKind::Point ? 0.0f : rng.draw();
    if (!sampleLight(scene, light, vertex.origin, u0, u1, u2, ls)) return false;
    const Material& material = scene.materials[vertex.material];
    float pdfBsdf;
    Vec3f fCos{1, 1, 1};
    octaves = CloudOctaves{};
    if (vertex.inCloud) {  // the phase function (its value is its pdf) goes with the octaves' weights
        octaves = cloudLightOctaves(scene.cloudLayers[0], -dot(ls.dir, vertex.wo), !vertex.bsdfStrategy);
        pdfBsdf = octaves.weight[0];
    } else {
        fCos = evalBsdf(material, vertex.wo, ls.dir, vertex.normal, pdfBsdf);
    }
    const float lightPdf = pmf * ls.pdf;
    if (!(maxComponent(fCos) > 0.0f) || !(lightPdf > 0.0f)) return false;
    const float weight = vertex.bsdfStrategy ? lightSampleWeight(light.kind, settings.lightSamples, lightPdf, pdfBsdf) : 1.0f;
    contribution = vertex.throughput * fCos * ls.radiance * (weight / (float(settings.lightSamples) * lightPdf));
    if (!(maxComponent(contribution) > 0.0f)) return false;
    shadow = shadowRayTowards(vertex.origin, ls);
    return true;
}

/// Russian roulette for the path of `depth` vertices going on with `throughput` (divided by the
/// survival probability where it survives); true unless it is lost.
URBIS_HD inline bool survivesRoulette(uint32_t depth, const RenderSettings& settings, Vec3f& throughput, SampleStream& rng) {
    if (depth + 1 < settings.rrDepth) return true;
    const float survival = fminf(maxComponent(throughput), settings.rrSurvival);
    throughput *= 1.0f / survival;
    return rng.draw() < survival;
}

/// Traces the path of sample `sampleIndex` through pixel (px, py); pure function of its arguments.
/// Every ray, the path's and the light samples' shadow rays, is traced at the one call of
/// traceScene in the loop, so that the GPU kernel holds one copy of the traversal: after a vertex is
/// shaded, its settings.lightSamples shadow rays come next, one per iteration, then the path's
/// next ray. A medium step joins the same way, as one more kind of next ray.
URBIS_HD inline PathSample tracePath(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                     uint32_t px, uint32_t py, uint32_t sampleIndex) {
    SampleStream rng = pixelSampleStream(settings, px, py, sampleIndex);
    Ray pathRay = cameraSampleRay(camera, settings, px, py, rng);
    PathSample out;
    Vec3f throughput{1, 1, 1};
    BounceInfo bounce;
    PathVertex vertex;
    Ray ray = pathRay;
    Vec3f shadowContribution;       // what the shadow ray in flight adds if nothing blocks it
    CloudOctaves shadowOctaves;     // and how the clouds' transmittance weighs it
    bool tracingShadow = false, pathEnds = false;
    uint32_t lightSamplesLeft = 0;
    const LightsView& lights = scene.lights;
    WaterPath water;                // the absorption of the water the path is in
    for (uint32_t depth = 0;;) {
        const SurfaceHit hit = traceScene(scene, ray, tracingShadow);
        ++out.rays;
        if (tracingShadow) {
            if (!hit.valid()) out.radiance += shadowContribution * cloudTransmittance(scene, ray, shadowOctaves, rng);
        } else if (float tCloud; cloudCollision(scene, ray, hit.valid() ? hit.t : ray.tmax, rng, tCloud)) {
            // A droplet of a cloud before any surface: the path scatters there by the phase function.
            applySegmentMedium(scene, ray, tCloud, throughput, out.radiance);
            const CloudLayer& layer = scene.cloudLayers[0];
            const Vec3f dir = normalize(ray.dir);
            throughput *= layer.albedo;
            vertex = PathVertex{ray.origin + ray.dir * tCloud, Vec3f{}, -dir, throughput, 0, depth + 1 < settings.maxDepth, true};
            lightSamplesLeft = settings.lightSamples;
            bool goesOn = vertex.bsdfStrategy;
            if (goesOn) {
                const CloudPhase phase = cloudPhase(layer);
                const float uLobe = rng.draw(), u1 = rng.draw(), u2 = rng.draw();
                const Vec3f next = sampleCloudPhase(phase, dir, uLobe, u1, u2);
                bounce = BounceInfo{cloudPhaseValue(phase, dot(dir, next)), false, false, lightContext(vertex)};
                goesOn = survivesRoulette(depth, settings, throughput, rng);
                pathRay = Ray{vertex.origin, next};
            }
            pathEnds = !goesOn;
            depth += goesOn;
        } else if (!hit.valid()) {
            throughput *= water.transmittance(3.0e38f);   // below a water's surface nothing comes from afar
            // The sky, and the sun's disk: found by BSDF sampling, weighed against light sampling
            // (their pdfs only where the weight needs them: not for camera rays and specular bounces).
            const Vec3f dir = normalize(ray.dir);
            const LightRecord sky{LightKind::Sky, 0, 0.0f};
            float skyWeight = 1.0f;
            if (!bounce.countsInFull && lights.skyLight != kNoLight)
                skyWeight = bsdfFoundWeight(bounce, LightKind::Sky, settings.lightSamples,
                                            lightSelectionPmf(lights, settings.lightSampler, bounce.from, lights.skyLight),
                                            lightPdf(scene, sky, dir, 0.0f, 0.0f));
            out.radiance += throughput * skyRadianceFrom(scene, ray.origin, dir) * skyWeight;
            // The camera ray (depth 0) does not show the sun's disk.
            if (depth > 0 && sunEnabled(scene.sun) && sunContains(scene.sun, dir)) {
                float sunWeight = 1.0f;
                if (!bounce.countsInFull)
                    sunWeight = bsdfFoundWeight(bounce, LightKind::Sun, settings.lightSamples,
                                                lightSelectionPmf(lights, settings.lightSampler, bounce.from, lights.sunLight),
                                                sunPdf(scene.sun));
                out.radiance += throughput * scene.sun.radiance * diskTransmittanceFrom(scene, ray.origin, dir) * sunWeight;
            }
            // The moon's disk, which camera rays see too, and the stars (lights/star_field.h).
            if (sunContains(scene.night.moon, dir)) {
                float moonWeight = 1.0f;
                if (!bounce.countsInFull)
                    moonWeight = bsdfFoundWeight(bounce, LightKind::Moon, settings.lightSamples,
                                                 lightSelectionPmf(lights, settings.lightSampler, bounce.from, lights.moonLight), 0.0f);
                out.radiance += throughput * scene.night.moon.radiance * moonWeight;
            }
            out.radiance += throughput * nightSkyRadiance(scene.night.stars, dir);
            pathEnds = true;
        } else {
            applySegmentMedium(scene, ray, hit.t, throughput, out.radiance);
            throughput *= water.transmittance(hit.t * length(ray.dir));
            const Material& material = scene.materials[hit.material];
            const Vec3f dir = normalize(ray.dir);
            out.radiance += throughput * foundEmission(scene, settings, hit, material, ray, dir, bounce);
            const Vec3f offset = rayOriginOffset(hit.position, hit.normal);
            vertex.origin = hit.position + offset;
            vertex.normal = hit.normal;
            vertex.wo = -dir;
            vertex.throughput = throughput;
            vertex.material = hit.material;
            vertex.inCloud = false;
            const bool scatters = !isSpecular(material);
            // The path goes on unless it is deep enough, is absorbed or loses the Russian roulette.
            BsdfSample bsdf;
            bool goesOn = depth + 1 < settings.maxDepth;
            // Whether BSDF sampling is a strategy here does not depend on how its sample turns out
            // (absorbed, below the surface, lost to Russian roulette): the light samples' weights must not.
            vertex.bsdfStrategy = goesOn;
            float nextTmin = 0.0f;          // past a water's skipBelow for a ray refracted into it
            if (goesOn) {
                float u3 = rng.draw(), u4 = rng.draw();
                float u5 = material.kind == MaterialKind::Lambertian ? 0.0f : rng.draw();
                const bool isWater = material.kind == MaterialKind::Water;
                const Vec3f n = isWater ? waterShadingNormal(material, hit.position, hit.normal, vertex.wo) : vertex.normal;
                goesOn = sampleBsdf(material, vertex.wo, n, u5, u3, u4, bsdf);
                nextTmin = goesOn && isWater ? water.scattered(material, n, hit.normal, bsdf) : 0.0f;
            }
            if (goesOn) {
                throughput *= bsdf.weight;
                bounce = bounceAfter(bounce, vertex, material, bsdf);
                goesOn = survivesRoulette(depth, settings, throughput, rng);
            }
            lightSamplesLeft = scatters ? settings.lightSamples : 0;
            pathEnds = !goesOn;
            if (goesOn) {
                pathRay = Ray{dot(bsdf.dir, hit.normal) > 0.0f ? vertex.origin : hit.position - offset, bsdf.dir, nextTmin};
                ++depth;
            }
        }
        // The next ray: the vertex's pending light samples first, then the path's own.
        tracingShadow = false;
        while (lightSamplesLeft > 0 && !tracingShadow) {
            --lightSamplesLeft;
            tracingShadow = sampleShadowRay(scene, settings, vertex, rng, ray, shadowContribution, shadowOctaves);
        }
        if (tracingShadow) continue;
        if (pathEnds) break;
        ray = pathRay;
    }
    return out;
}

} // namespace urbis
