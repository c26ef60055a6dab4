// The sky as an environment light (host+device): its radiance, and directions importance-sampled
// from a piecewise-constant table of that radiance over a lat-long map (pbrt-v3 InfiniteAreaLight;
// the table is built once per scene by buildLights). Map: u = phi / 2 pi with phi the azimuth from
// +x towards +z, v = theta / pi with theta from +y (up).
#pragma once

#include "math/piecewise_constant.h"
#include "math/sampling.h"
#include "scene/sky.h"

namespace urbis {

/// Radiance seen along a unit world direction (y up). The sun's disk is not part of it.
URBIS_HD inline Vec3f skyRadiance(const Sky& sky, Vec3f dir) {
    if (dir.y < 0.0f) return sky.ground;
    float w = powf(dir.y, sky.exponent);
    return sky.zenith * w + sky.horizon * (1.0f - w);
}

/// The unit direction at (u, v) of the lat-long map.
URBIS_HD inline Vec3f skyDirectionFromUv(Vec2f uv) {
    float theta = kPi * uv.y, phi = 2.0f * kPi * uv.x;
    float sinTheta = sinf(theta);
    return {sinTheta * cosf(phi), cosf(theta), sinTheta * sinf(phi)};
}

/// (u, v) of a unit direction on the lat-long map.
URBIS_HD inline Vec2f skyUvFromDirection(Vec3f dir) {
    float phi = atan2f(dir.z, dir.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return {phi / (2.0f * kPi), acosf(fminf(1.0f, fmaxf(-1.0f, dir.y))) / kPi};
}

/// A direction distributed as the table (uniform over the sphere without one) and its solid-angle
/// pdf; the map's Jacobian is 2 pi^2 sin(theta).
URBIS_HD inline Vec3f sampleSkyDirection(const PiecewiseConstant2DView& table, float u1, float u2, float& pdf) {
    if (table.empty()) {
        pdf = uniformSpherePdf();
        return sampleUniformSphere(u1, u2);
    }
    float uvPdf;
    const Vec2f uv = samplePiecewiseConstant2D(table, u1, u2, uvPdf);
    const Vec3f dir = skyDirectionFromUv(uv);
    const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - dir.y * dir.y));
    pdf = sinTheta > 0.0f ? uvPdf / (2.0f * kPi * kPi * sinTheta) : 0.0f;
    return dir;
}

/// The solid-angle pdf with which sampleSkyDirection returns the unit direction `dir`.
URBIS_HD inline float skyDirectionPdf(const PiecewiseConstant2DView& table, Vec3f dir) {
    if (table.empty()) return uniformSpherePdf();
    const Vec2f uv = skyUvFromDirection(dir);
    const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - dir.y * dir.y));
    return sinTheta > 0.0f ? piecewiseConstant2DPdf(table, uv) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

} // namespace urbis
