// The light interface (host+device): one light of the closed set (scene/light_records.h) sampled
// from a shading point, and the pdf of a direction that reached it by other means. A switch over
// the record's tag; each kind's functions live in its own header.
#pragma once

#include "lights/emissive_surface_light.h"
#include "lights/lamp_light.h"
#include "lights/sky_light.h"
#include "lights/sun_light.h"
#include "lights/window_light.h"
#include "scene/scene_view.h"

namespace urbis {

/// A direction towards a light from a shading point.
struct LightSample {
    Vec3f dir;                ///< unit, world space
    Vec3f radiance;           ///< arriving along -dir, before visibility
    float pdf = 0;            ///< solid angle, given that this light was chosen
    float distance = 3.0e38f; ///< to the point sampled; infinite lights: the largest float
};

/// The disk of a light of kind Sun or Moon: both are the sun's record (lights/sun_light.h).
URBIS_HD inline const Sun& diskLight(const SceneView& scene, LightKind kind) {
    return kind == LightKind::Moon ? scene.night.moon : scene.sun;
}

/// Samples `light` as seen from `from` with three uniform numbers. Returns false when it gives
/// nothing there (a disabled sun, an edge-on surface, no lit window found, a reserved kind).
URBIS_HD inline bool sampleLight(const SceneView& scene, const LightRecord& light, Vec3f from, float u0, float u1,
                                 float u2, LightSample& s) {
    switch (light.kind) {
    case LightKind::Sun:
    case LightKind::Moon: {
        const Sun& disk = diskLight(scene, light.kind);
        if (!sunEnabled(disk)) return false;
        s.dir = sampleSunDirection(disk, u1, u2);
        s.radiance = disk.radiance * diskTransmittanceFrom(scene, from, s.dir);
        s.pdf = sunPdf(disk);
        return true;
    }
    case LightKind::Sky:
        s.dir = sampleSkyDirection(scene.lights.skyTable, u1, u2, s.pdf);
        s.radiance = skyRadiance(scene, s.dir);
        return s.pdf > 0.0f;
    case LightKind::EmissiveSurface: {
        const EmissiveSurface& surface = scene.lights.surfaces[light.index];
        s.radiance = surface.emission;
        return sampleEmissiveSurface(scene.lights.triangles, surface, from, u0, u1, u2, s.dir, s.distance, s.pdf);
    }
    case LightKind::Point:
        return sampleLampLight(scene.lights.lampLights[light.index], from, s.dir, s.radiance, s.distance, s.pdf);
    case LightKind::Aggregate: {
        const WallRecord& wall = scene.walls[light.index];
        const Vec3f room = scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)].emission;
        const Material& glass = scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::Glass)];
        return sampleWallWindows(wall, light.litCells, room, glass, from, u0, u1, u2, s.dir, s.distance, s.pdf, s.radiance);
    }
    case LightKind::Spot:
        return false;
    }
    return false;
}

/// Solid-angle pdf with which sampleLight(light) returns the unit direction `dir`, when that
/// direction reaches the light at `distance` where its surface makes cosine `cosLight` with `dir`
/// (those two matter for surfaces only); `from` is the shading point, which an aggregate's pdf needs.
URBIS_HD inline float lightPdf(const SceneView& scene, const LightRecord& light, Vec3f dir, float distance,
                               float cosLight, Vec3f from = {}) {
    switch (light.kind) {
    case LightKind::Sun:
    case LightKind::Moon: {
        const Sun& disk = diskLight(scene, light.kind);
        return sunEnabled(disk) && sunContains(disk, dir) ? sunPdf(disk) : 0.0f;
    }
    case LightKind::Sky:
        return skyDirectionPdf(scene.lights.skyTable, dir);
    case LightKind::EmissiveSurface:
        return emissiveSurfacePdf(scene.lights.surfaces[light.index], distance, cosLight);
    case LightKind::Aggregate:  // `dir` from the shading point `from`
        return wallWindowsPdf(scene.walls[light.index], light.litCells, from, dir);
    case LightKind::Point:      // a delta light: no direction reaches it by BSDF sampling
    case LightKind::Spot:
        return 0.0f;
    }
    return 0.0f;
}

} // namespace urbis
