// The sky as an environment light (host+device): its radiance (analytic or the atmosphere's), and directions importance-sampled
// from a piecewise-constant table of that radiance over an equal-area map of the sphere (pbrt-v3
// InfiniteAreaLight's method; the table is built once per scene by buildLights). Map (Lambert's
// cylindrical equal-area projection): u = phi / 2 pi with phi the azimuth from +x towards +z,
// v = (1 - cos theta) / 2 with theta from +y (up). Every cell covers the same solid angle, so the
// map's Jacobian is the constant 4 pi: no sin theta and no acos per ray, which keeps the GPU's
// render kernel smaller (docs/gpu_notes.md § Instruction cache).
#pragma once

#include "math/piecewise_constant.h"
#include "math/sampling.h"
#include "media/atmosphere_lut.h"
#include "media/planet_atmosphere.h"
#include "scene/scene_view.h"

namespace urbis {

/// Radiance of the analytic sky along a unit world direction (y up).
URBIS_HD inline Vec3f analyticSkyRadiance(const Sky& sky, Vec3f dir) {
    if (dir.y < 0.0f) return sky.ground;
    float w = powf(dir.y, sky.exponent);
    return sky.zenith * w + sky.horizon * (1.0f - w);
}

/// Radiance of the scene's sky along a unit world direction (y up): the analytic sky, or the
/// atmosphere's sky view table (Hillaire 2020 § 5.3), which holds the in-scattered light of the whole
/// ray from the world's origin, so that a miss adds no aerial perspective of its own. The sun's disk
/// is not part of it.
URBIS_HD inline Vec3f skyRadiance(const SceneView& scene, Vec3f dir) {
    if (scene.sky.model == SkyModel::Analytic) return analyticSkyRadiance(scene.sky, dir);
    return lutBilinear(scene.skyViewLut, kSkyViewLutWidth, kSkyViewLutHeight, skyViewLutCoord(scene.sky.atmosphere, dir));
}

/// The sky's radiance along a ray from the world point `origin` in the unit direction `dir` that meets
/// no surface: skyRadiance in a city; around a planet, the atmosphere marched from `origin` (in orbit
/// or on the ground), since one table seen from one point cannot hold both.
URBIS_HD inline Vec3f skyRadianceFrom(const SceneView& scene, Vec3f origin, Vec3f dir) {
    const PlanetRecord* pl = scenePlanet(scene);
    if (pl && scene.sky.model == SkyModel::Atmosphere) return planetSkyRadiance(scene, *pl, origin, dir);
    return skyRadiance(scene, dir);
}

/// The unit direction at (u, v) of the map.
URBIS_HD inline Vec3f skyDirectionFromUv(Vec2f uv) {
    const float cosTheta = 1.0f - 2.0f * uv.y, phi = 2.0f * kPi * uv.x;
    const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * cosf(phi), cosTheta, sinTheta * sinf(phi)};
}

/// (u, v) of a unit direction on the map.
URBIS_HD inline Vec2f skyUvFromDirection(Vec3f dir) {
    float phi = atan2f(dir.z, dir.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return {phi / (2.0f * kPi), fminf(1.0f, fmaxf(0.0f, 0.5f * (1.0f - dir.y)))};
}

/// The map's constant Jacobian: solid angle per unit of (u, v) area.
inline constexpr float kSkyMapSolidAngle = 4.0f * kPi;

/// A direction distributed as the table and its solid-angle pdf. The sky is a light only with a
/// table (buildLights), so the table is never empty here.
URBIS_HD inline Vec3f sampleSkyDirection(const PiecewiseConstant2DView& table, float u1, float u2, float& pdf) {
    float uvPdf;
    const Vec2f uv = samplePiecewiseConstant2D(table, u1, u2, uvPdf);
    pdf = uvPdf / kSkyMapSolidAngle;
    return skyDirectionFromUv(uv);
}

/// The solid-angle pdf with which sampleSkyDirection returns the unit direction `dir`.
URBIS_HD inline float skyDirectionPdf(const PiecewiseConstant2DView& table, Vec3f dir) {
    return piecewiseConstant2DPdf(table, skyUvFromDirection(dir)) / kSkyMapSolidAngle;
}

} // namespace urbis
