// The path tracer's lights (host+device): what its rays find emitted, where they hit a surface or
// meet nothing, and its light samples, each weighed against the other strategy by the power
// heuristic (Veach 1997, chapter 9). What a hit emits comes from its primitive kind's trait
// (KindIntersector<Record>::Emitter, as pbrt-v4's Le); what a ray that meets nothing sees, from the
// infinite light kinds; how a light sample draws its numbers and whether MIS weighs it, from its
// light kind's traits. No kind is named here.
#pragma once

#include "geometry/scene_intersect.h"
#include "integrators/path_vertex.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights/mis.h"
#include "lights/star_field.h"
#include "media/cloud_scattering.h"
#include "scene/render_settings.h"

#include <utility>

namespace urbis {

/// Weight of emission of a light of kind `kind` that a BSDF sample of solid-angle pdf `bsdfPdf` found
/// at a point that `lightSamples` light samples, picking that light with `selectionPmf`, reach with
/// solid-angle pdf `pdf`. A kind that MIS does not weigh leaves it to its light samples (weight 0).
URBIS_HD inline float bsdfFoundWeight(float bsdfPdf, uint32_t kind, uint32_t lightSamples, float selectionPmf, float pdf) {
    if (lightSamples == 0 || !(selectionPmf > 0.0f)) return 1.0f;
    if (!lightKindMisWeighs(kind)) return 0.0f;
    return powerHeuristic(1.0f, bsdfPdf, float(lightSamples), selectionPmf * pdf);
}

/// Weight of what a ray of `bounce` found emitted by light `lightOf()` (kNoLight: none) of kind `Light`
/// in the unit direction `dir`, at `distance` where its surface makes cosine `cosLight` with `dir`.
/// Camera rays and specular bounces count it in full, but for a kind found through panes, which a
/// ray of a window path finds as the light samples of the vertex it left would (BounceInfo::windowPath).
template <typename Light, typename LightOf>
URBIS_HD inline float foundWeight(const SceneView& scene, const RenderSettings& settings, const BounceInfo& bounce,
                                  LightOf lightOf, Vec3f dir, float distance, float cosLight) {
    const bool weighs = Light::kFoundThroughPanes ? bounce.windowPath : !bounce.countsInFull;
    if (!weighs || settings.lightSamples == 0) return 1.0f;
    const uint32_t light = lightOf();
    if (light == kNoLight) return 1.0f;
    // Every sampler picks an infinite light of the list with a positive probability everywhere (its
    // power is positive, and the infinite lights have a share of every choice), so where MIS does not
    // weigh it, its light samples carry all of it. No pick probability then: the GPU's render kernel
    // holds one inlined copy of lightSelectionPmf per call, and the escape calls it per infinite kind.
    if constexpr (Light::kInfinite && !Light::kMisWeighs) return 0.0f;
    const float pmf = lightSelectionPmf(scene, settings.lightSampler, bounce.from, light);
    if constexpr (!Light::kMisWeighs) return pmf > 0.0f ? 0.0f : 1.0f;
    else return bsdfFoundWeight(bounce.pdf, kLightKindOf<Light>, settings.lightSamples, pmf,
                                Light::pdf(scene, lightRecord(scene, light), bounce.from.p, dir, distance, cosLight));
}

/// Weight of one of `lightSamples` light samples of a light of kind `kind`, of solid-angle pdf
/// `lightPdf` (selection included), against the BSDF sample of the same vertex, which would find
/// that direction with `bsdfPdf`.
URBIS_HD inline float lightSampleWeight(uint32_t kind, uint32_t lightSamples, float lightPdf, float bsdfPdf) {
    if (!lightKindMisWeighs(kind)) return 1.0f;
    return powerHeuristic(float(lightSamples), lightPdf, 1.0f, bsdfPdf);
}

template <uint32_t I>
inline constexpr bool kKindEmits = requires { typename KindIntersector<PrimRecord<I>>::Emitter; };

/// What a ray finds emitted at `hit` of primitive kind `I`: its light kind's emittedAt, weighed where
/// that light kind's light samples reach it too; a kind without an emitter shows its material's.
template <uint32_t I>
URBIS_HD inline Vec3f foundKindEmission(const SceneView& scene, const RenderSettings& settings, const SurfaceHit& hit,
                                        const Material& material, const Ray& ray, Vec3f dir, const BounceInfo& bounce) {
    if constexpr (kKindEmits<I>) {
        using Light = typename KindIntersector<PrimRecord<I>>::Emitter;
        const EmissionAtHit e = Light::emittedAt(scene, hit, material, ray, dir);
        if (!e.lightSampled) return e.radiance;
        return e.radiance * foundWeight<Light>(scene, settings, bounce, [&] { return Light::lightAt(scene, hit); }, dir,
                                               hit.t * length(ray.dir), dot(hit.normal, dir));
    } else {
        return materialEmission(material);
    }
}

template <uint32_t... I>
URBIS_HD inline Vec3f foundEmissionOver(const SceneView& scene, const RenderSettings& settings, const SurfaceHit& hit,
                                        const Material& material, const Ray& ray, Vec3f dir, const BounceInfo& bounce,
                                        std::integer_sequence<uint32_t, I...>) {
    Vec3f out;
    const bool emits = ((kKindEmits<I> && hit.kind == I &&
                         (out = foundKindEmission<I>(scene, settings, hit, material, ray, dir, bounce), true)) ||
                        ...);
    return emits ? out : materialEmission(material);
}

/// What a ray of `bounce` with unit direction `dir` finds emitted at `hit` (of `material`), weighed
/// against the light samples that reach it: a fold over the primitive kinds that have an emitter.
URBIS_HD inline Vec3f foundEmission(const SceneView& scene, const RenderSettings& settings, const SurfaceHit& hit,
                                    const Material& material, const Ray& ray, Vec3f dir, const BounceInfo& bounce) {
    return foundEmissionOver(scene, settings, hit, material, ray, dir, bounce,
                             std::make_integer_sequence<uint32_t, kPrimKindCount>{});
}

template <uint32_t... I>
URBIS_HD inline void addEscapedEmissionOver(const SceneView& scene, const RenderSettings& settings, const Ray& ray,
                                            Vec3f dir, uint32_t depth, const BounceInfo& bounce, Vec3f throughput,
                                            Vec3f& radiance, std::integer_sequence<uint32_t, I...>) {
    const auto add = [&](auto kind) {
        using Light = typename decltype(kind)::Light;
        if constexpr (Light::kInfinite) {
            Vec3f seen;
            if (Light::escaped(scene, ray.origin, dir, depth, seen))
                radiance += throughput * seen *
                            foundWeight<Light>(scene, settings, bounce, [&] { return scene.lights.first<Light>(); }, dir,
                                               0.0f, 0.0f);
        }
    };
    (add(LightKindTag<I>{}), ...);
}

/// Adds to `radiance` what a ray of `bounce` that meets nothing (unit direction `dir`, the path's
/// vertex `depth`) sees: the infinite lights, in the list's order, each weighed against its light
/// samples (their pdfs only where the weight needs them: not for camera rays and specular bounces),
/// then the stars (lights/star_field.h), which no light sample draws.
URBIS_HD inline void addEscapedEmission(const SceneView& scene, const RenderSettings& settings, const Ray& ray, Vec3f dir,
                                        uint32_t depth, const BounceInfo& bounce, Vec3f throughput, Vec3f& radiance) {
    addEscapedEmissionOver(scene, settings, ray, dir, depth, bounce, throughput, radiance,
                           std::make_integer_sequence<uint32_t, kLightKindCount>{});
    radiance += throughput * nightSkyRadiance(scene.night.stars, dir);
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
    // there is more than one, then what the light's kind reads (lightKindPicks, lightKindPlaces).
    const float uLight = lightCount(scene) > 1 ? rng.draw() : 0.0f;
    float pmf;
    const uint32_t index = selectLight(scene, settings.lightSampler, lightContext(vertex), uLight, pmf);
    if (!(pmf > 0.0f)) return false;
    LightSample ls;
    const LightRecord light = lightRecord(scene, index);
    const float u0 = lightKindPicks(light.kind) ? rng.draw() : 0.0f;
    const bool places = lightKindPlaces(light.kind);
    const float u1 = places ? rng.draw() : 0.0f, u2 = places ? rng.draw() : 0.0f;
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

} // namespace urbis
