// The light interface (host+device): one light of the closed set (scene/light_records.h) sampled
// from a shading point, and the pdf of a direction that reached it by other means. A switch over
// the record's tag; each kind's functions live in its own header.
#pragma once

#include "lights/emissive_surface_light.h"
#include "lights/sky_light.h"
#include "lights/sun_light.h"
#include "scene/scene_view.h"

namespace urbis {

/// A direction towards a light from a shading point.
struct LightSample {
    Vec3f dir;                ///< unit, world space
    Vec3f radiance;           ///< arriving along -dir, before visibility
    float pdf = 0;            ///< solid angle, given that this light was chosen
    float distance = 3.0e38f; ///< to the point sampled; infinite lights: the largest float
};

/// Samples `light` as seen from `from` with three uniform numbers. Returns false when it gives
/// nothing there (a disabled sun, an edge-on surface, a reserved kind).
URBIS_HD inline bool sampleLight(const SceneView& scene, const LightRecord& light, Vec3f from, float u0, float u1,
                                 float u2, LightSample& s) {
    switch (light.kind) {
    case LightKind::Sun:
        if (!sunEnabled(scene.sun)) return false;
        s.dir = sampleSunDirection(scene.sun, u1, u2);
        s.radiance = scene.sun.radiance;
        s.pdf = sunPdf(scene.sun);
        return true;
    case LightKind::Sky:
        s.dir = sampleSkyDirection(scene.lights.skyTable, u1, u2, s.pdf);
        s.radiance = skyRadiance(scene, s.dir);
        return s.pdf > 0.0f;
    case LightKind::EmissiveSurface: {
        const EmissiveSurface& surface = scene.lights.surfaces[light.index];
        s.radiance = surface.emission;
        return sampleEmissiveSurface(scene.lights.triangles, surface, from, u0, u1, u2, s.dir, s.distance, s.pdf);
    }
    case LightKind::Point:      // lamps sample their position and evaluate their profile here
    case LightKind::Spot:
    case LightKind::Aggregate:  // an aggregate picks one of its emitters (a lit window) here
        return false;
    }
    return false;
}

/// Solid-angle pdf with which sampleLight(light) returns the unit direction `dir`, when that
/// direction reaches the light at `distance` where its surface makes cosine `cosLight` with `dir`
/// (the last two matter for surfaces only).
URBIS_HD inline float lightPdf(const SceneView& scene, const LightRecord& light, Vec3f dir, float distance,
                               float cosLight) {
    switch (light.kind) {
    case LightKind::Sun:
        return sunEnabled(scene.sun) && sunContains(scene.sun, dir) ? sunPdf(scene.sun) : 0.0f;
    case LightKind::Sky:
        return skyDirectionPdf(scene.lights.skyTable, dir);
    case LightKind::EmissiveSurface:
        return emissiveSurfacePdf(scene.lights.surfaces[light.index], distance, cosLight);
    case LightKind::Point:      // delta lights: no direction reaches them by BSDF sampling
    case LightKind::Spot:
    case LightKind::Aggregate:
        return 0.0f;
    }
    return 0.0f;
}

} // namespace urbis
