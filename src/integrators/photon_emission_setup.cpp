#include "integrators/photon_emission_setup.h"

#include "lights/light.h"
#include "lights/light_sampler.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// Flux of the upper hemisphere of the sky through the sphere's disk: pi r^2 times the integral of
/// its luminance over the hemisphere (midpoint rule, 64 x 16 directions).
float skyFlux(const SceneView& view, float radius) {
    constexpr int kPhi = 64, kCos = 16;
    double sum = 0;
    for (int j = 0; j < kCos; ++j)
        for (int i = 0; i < kPhi; ++i) {
            const float cosTheta = (j + 0.5f) / kCos, phi = 2.0f * kPi * (i + 0.5f) / kPhi;
            const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
            sum += luminance(skyRadiance(view, Vec3f{sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)}));
        }
    return float(sum * (2.0 * kPi / (kPhi * kCos)) * kPi * radius * radius);
}

/// Flux of light `record` as emitPhoton sends it: the disks through the sphere's disk, the rest by
/// their own power (lights/light_build.cpp).
float listLightFlux(const SceneView& view, const LightRecord& record, float radius) {
    switch (record.kind) {
    case LightKind::Sun:
    case LightKind::Moon: {
        const Sun& disk = diskLight(view, record.kind);
        return sunEnabled(disk) ? luminance(disk.radiance) / sunPdf(disk) * kPi * radius * radius : 0.0f;
    }
    case LightKind::Sky: return skyFlux(view, radius);
    default: return record.power;
    }
}

} // namespace

PhotonsView photonEmissionOf(const Scene& scene, const SceneView& view) {
    Bounds3f bounds;
    for (const Triangle& t : scene.triangles) bounds.extend(primBounds(t));
    for (const WallRecord& w : scene.walls) bounds.extend(primBounds(w));
    for (const LampRecord& l : scene.lamps) bounds.extend(primBounds(l));
    if (bounds.empty()) bounds = {{-1, 0, -1}, {1, 1, 1}};
    PhotonsView photons;
    photons.centre = bounds.centre();
    photons.radius = std::max(0.5f * length(bounds.extent()), 1.0f);
    if (view.lights.skyLight == kNoLight) {
        const float sky = skyFlux(view, photons.radius);
        float list = 0;
        for (uint32_t i = 0; i < lightCount(view.lights); ++i) list += listLightFlux(view, lightRecord(view.lights, i), photons.radius);
        photons.skyPmf = sky > 0.0f ? sky / (sky + list) : 0.0f;
    }
    return photons;
}

float photonEmittedFlux(const SceneView& view, const PhotonsView& photons) {
    float flux = photons.skyPmf > 0.0f ? skyFlux(view, photons.radius) : 0.0f;
    for (uint32_t i = 0; i < lightCount(view.lights); ++i) flux += listLightFlux(view, lightRecord(view.lights, i), photons.radius);
    return flux;
}

float photonFixedScale(const SceneView& view, const PhotonsView& photons, const RenderSettings& settings) {
    const float perPhoton = photonEmittedFlux(view, photons) / float(std::max(settings.photonsPerPass, 1u));
    const float splat = perPhoton / (settings.photonTexel * settings.photonTexel);
    return splat > 0.0f ? 0x1p30f / splat : 1.0f;
}

} // namespace urbis
