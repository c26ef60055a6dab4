#include "integrators/photon_emission_setup.h"

#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights/scene_sphere.h"

#include <algorithm>

namespace urbis {

namespace {

/// Flux of light `record` as its photons carry it (its kind's photonFlux).
float listLightFlux(const SceneView& view, const LightRecord& record, float radius) {
    return dispatchLight(record.kind, [&](auto kind) { return decltype(kind)::Light::photonFlux(view, record, radius); });
}

/// `flux` plus the flux of every light of the list, added in the list's order.
float addListFlux(const SceneView& view, float radius, float flux) {
    for (uint32_t i = 0; i < lightCount(view); ++i) flux += listLightFlux(view, lightRecord(view, i), radius);
    return flux;
}

} // namespace

PhotonsView photonEmissionOf(const Scene& scene, const SceneView& view) {
    const SceneSphere sphere = lightSceneSphere(scene);
    PhotonsView photons;
    photons.centre = sphere.centre;
    photons.radius = sphere.radius;
    if (view.lights.first<SkyLight>() == kNoLight) {
        const float sky = skyHemisphereFlux(view, photons.radius);
        const float list = addListFlux(view, photons.radius, 0.0f);
        photons.skyPmf = sky > 0.0f ? sky / (sky + list) : 0.0f;
    }
    return photons;
}

float photonEmittedFlux(const SceneView& view, const PhotonsView& photons) {
    return addListFlux(view, photons.radius, photons.skyPmf > 0.0f ? skyHemisphereFlux(view, photons.radius) : 0.0f);
}

float photonFixedScale(const SceneView& view, const PhotonsView& photons, const RenderSettings& settings) {
    const float perPhoton = photonEmittedFlux(view, photons) / float(std::max(settings.photonsPerPass, 1u));
    const float splat = perPhoton / (settings.photonTexel * settings.photonTexel);
    return splat > 0.0f ? 0x1p30f / splat : 1.0f;
}

} // namespace urbis
