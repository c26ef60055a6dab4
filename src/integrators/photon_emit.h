// Photon emission (host+device): a photon leaves a light of the scene's list, picked in proportion to
// its power by the light sampler (lights/light_sampler.h, LightSamplerKind::Power), or the sky when the
// sky is not in the list (by day: docs/lights.md), with the flux that makes the photons of a pass an
// unbiased estimate of the emitted light. docs/photons.md § Emission.
#pragma once

#include "lights/light.h"
#include "lights/light_sampler.h"
#include "math/rng.h"
#include "scene/material.h"

namespace urbis {

/// A photon's first ray and its flux (renderer units, for one of `photonsPerPass`).
struct EmittedPhoton {
    Ray ray;
    Vec3f power;
    /// Whether its first hit is stored: its light is not light-sampled by the camera pass (the sky by
    /// day), so photons must carry its direct light too.
    bool depositFirst = false;
};

/// A ray from the disk of radius `radius` about `centre`, perpendicular to unit `towards` (where the
/// light is), that travels along -towards and starts outside the sphere: infinite lights reach every
/// point of the sphere through it, pi radius^2 of area.
URBIS_HD inline Ray rayFromDisk(Vec3f centre, float radius, Vec3f towards, float u1, float u2) {
    const Frame frame = Frame::fromZ(towards);
    const float r = radius * sqrtf(u1), phi = 2.0f * kPi * u2;
    const Vec3f origin = centre + towards * (1.01f * radius) + frame.x * (r * cosf(phi)) + frame.y * (r * sinf(phi));
    return Ray{origin, -towards};
}

/// A photon of the sky: a direction of the upper hemisphere, uniform (pdf 1 / 2 pi; the light
/// sampler's table leaves out what MIS compensation removed, so it cannot serve here), through the disk.
URBIS_HD inline EmittedPhoton skyPhoton(const SceneView& scene, float u1, float u2, float u3, float u4) {
    const Vec3f towards = Frame::fromZ(Vec3f{0, 1, 0}).toWorld(directionAtCosine(u1, u2));
    const float r = scene.photons.radius;
    return {rayFromDisk(scene.photons.centre, r, towards, u3, u4), skyRadiance(scene, towards) * (2.0f * kPi * kPi * r * r)};
}

/// Emits photon `index` of a pass of `count` from the scene's lights with the numbers of `rng`.
/// Returns false when it carries nothing (an unlit window, a lamp's dark side): it still counts as emitted.
URBIS_HD inline bool emitPhoton(const SceneView& scene, uint32_t count, SampleStream& rng, EmittedPhoton& out) {
    const PhotonsView& photons = scene.photons;
    const float u = rng.draw(), u1 = rng.draw(), u2 = rng.draw(), u3 = rng.draw(), u4 = rng.draw();
    const float perPhoton = 1.0f / float(count);
    if (u < photons.skyPmf) {
        out = skyPhoton(scene, u1, u2, u3, u4);
        out.power *= perPhoton / photons.skyPmf;
        out.depositFirst = true;
        return maxComponent(out.power) > 0.0f;
    }
    float pmf;
    const float uList = (u - photons.skyPmf) / (1.0f - photons.skyPmf);
    const uint32_t index = selectLight(scene.lights, LightSamplerKind::Power, LightSampleContext{}, fminf(uList, 0x1.fffffep-1f), pmf);
    if (!(pmf > 0.0f)) return false;
    const float scale = perPhoton / ((1.0f - photons.skyPmf) * pmf);
    const LightRecord light = lightRecord(scene.lights, index);
    out.depositFirst = false;
    switch (light.kind) {
    case LightKind::Sun:
    case LightKind::Moon: {
        const Sun& disk = diskLight(scene, light.kind);
        if (!sunEnabled(disk)) return false;
        const Vec3f towards = sampleSunDirection(disk, u1, u2);
        const float r = photons.radius;
        out.ray = rayFromDisk(photons.centre, r, towards, u3, u4);
        out.power = disk.radiance * (kPi * r * r / sunPdf(disk) * scale);
        break;
    }
    case LightKind::Sky:
        out = skyPhoton(scene, u1, u2, u3, u4);
        out.power *= scale;
        break;
    case LightKind::Point: {
        const LampEmitter& lamp = scene.lights.lampLights[light.index];
        const Vec3f dir = sampleUniformSphere(u1, u2);
        out.ray = Ray{lamp.position, dir, lamp.clearance};
        out.power = lampIntensity(lamp, dir) * (4.0f * kPi * scale);
        break;
    }
    case LightKind::EmissiveSurface: {
        // Both sides emit: a side by u3, a cosine-distributed direction about it (flux 2 pi A L).
        const EmissiveSurface& surface = scene.lights.surfaces[light.index];
        const TriangleLight& tri = pickTriangle(scene.lights.triangles, surface, u3);
        const Vec2f b = sampleUniformTriangle(u1, u2);
        const Vec3f e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
        const Vec3f n = normalize(cross(e1, e2)) * (u4 < 0.5f ? 1.0f : -1.0f);
        const Vec3f p = tri.p0 + e1 * b.x + e2 * b.y;
        const float v1 = rng.draw(), v2 = rng.draw();
        out.ray = Ray{p + n * 1e-3f, Frame::fromZ(n).toWorld(sampleCosineHemisphere(v1, v2))};
        out.power = surface.emission * (2.0f * kPi * surface.area * scale);
        break;
    }
    case LightKind::Aggregate: {
        // A lit cell of the tile (windowPickCell, as the light sampler picks it), a uniform point of
        // its glass, a cosine-distributed direction out of the wall, through the pane
        // (lights/window_light.h).
        const WallRecord& wall = scene.walls[light.index];
        uint32_t floor, slot;
        if (!windowPickCell(wall, light.litCells, u1, floor, slot)) return false;
        const CellLayout c = cellLayout(wall, floor, slot);
        const WindowRect r = windowRect(wall, c);
        if (!(r.area() > 0.0f)) return false;
        const float wu = r.u0 + (r.u1 - r.u0) * u2, wv = r.v0 + (r.v1 - r.v0) * u3;
        const Vec3f dir = Frame::fromZ(wall.normal).toWorld(sampleCosineHemisphere(u4, rng.draw()));
        const Vec3f room = scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)].emission;
        const Material& glass = scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::Glass)];
        out.ray = Ray{wall.worldFromWall(wu, wv, glassPlaneW(wall)) + wall.normal * 1e-3f, dir};
        out.power = windowRadiance(windowLook(wall, floor, slot), r, room, wu, wv) *
                    glassTransmission(glass, dot(dir, wall.normal)) *
                    (kPi * r.area() / windowPickPmf(tileCellCount(wall), light.litCells) * scale);
        break;
    }
    case LightKind::Spot:
        return false;
    }
    return maxComponent(out.power) > 0.0f;
}

} // namespace urbis
