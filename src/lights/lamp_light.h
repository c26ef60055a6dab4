// Street lamps as lights (host+device): a point at the glass's centre whose intensity follows a
// profile by head shape, normalised so that the lamp emits its luminous flux. Lamps are sampled
// as points (pbrt-v4's PointLight with a profile, as its GoniometricLight); the glass, seen by the
// camera or through a mirror, shows the radiance that spreads the same intensity over its
// projected area. A BSDF sample at a diffuse vertex that meets the glass counts nothing, since the
// point's light samples carry the lamp's light there (docs/lights.md § Lamps).
#pragma once

#include "math/constants.h"
#include "scene/light_bounds.h"
#include "scene/light_records.h"

namespace urbis {

/// Lux that one unit of the renderer's irradiance stands for: the default sun (SunDescription,
/// luminance 3.12) is about 100,000 lux of direct sunlight. So a radiance of 1 is 32,000 cd/m^2,
/// an intensity of 1 (radiance x m^2) is 32,000 cd, and a flux of 1 (irradiance x m^2) 32,000 lm.
inline constexpr float kLuxPerUnit = 32000.0f;

/// Exponent n of a full-cutoff head's profile cos^n (angle from straight down), zero above the
/// horizontal: a cobra head throws its light wide along the road, a flat panel and a cone's shade
/// narrower. Globes and lanterns (n < 0 here) have the nearly isotropic profile of lampProfile.
URBIS_HD inline float lampCutoffExponent(LampShape shape) {
    switch (shape) {
    case LampShape::Cobra: return 1.0f;
    case LampShape::Flat: return 2.0f;
    case LampShape::Cone: return 3.0f;
    case LampShape::Globe:
    case LampShape::Lantern: break;
    }
    return -1.0f;
}

/// The lamp's intensity towards a direction at cosine `cosDown` from straight down, relative to its
/// peak (1): cos^n below the horizontal for full-cutoff heads; a + (1 - a) cosDown for a globe
/// (a = 0.8) and a lantern under its roof (a = 0.6), brightest straight down.
URBIS_HD inline float lampProfile(LampShape shape, float cosDown) {
    const float n = lampCutoffExponent(shape);
    if (n > 0.0f) return cosDown > 0.0f ? powf(cosDown, n) : 0.0f;
    const float a = shape == LampShape::Globe ? 0.8f : 0.6f;
    return a + (1.0f - a) * cosDown;
}

/// The integral of lampProfile over the sphere of directions (sr): 2 pi / (n + 1) for cos^n over
/// the lower hemisphere, 4 pi a for a + (1 - a) cos over the sphere. Peak intensity = flux / this.
URBIS_HD inline float lampProfileIntegral(LampShape shape) {
    const float n = lampCutoffExponent(shape);
    if (n > 0.0f) return 2.0f * kPi / (n + 1.0f);
    return 4.0f * kPi * (shape == LampShape::Globe ? 0.8f : 0.6f);
}

/// Intensity (renderer units, radiance x m^2) that `lamp` sends towards unit direction `out`.
URBIS_HD inline Vec3f lampIntensity(const LampEmitter& lamp, Vec3f out) {
    return lamp.intensity * lampProfile(lamp.shape, -out.y);
}

/// Area (m^2) of the lamp's glass projected along unit direction `out`: a disc facing down (cobra,
/// cone, flat), a sphere (globe), a lantern's glass as a cylinder of its mean radius with its
/// bottom disc.
URBIS_HD inline float lampGlassProjectedArea(const LampEmitter& lamp, Vec3f out) {
    const float r = lamp.glassRadius, disc = kPi * r * r, down = -out.y;
    switch (lamp.shape) {
    case LampShape::Globe: return disc;
    case LampShape::Lantern: return 2.0f * r * lamp.glassHeight * sqrtf(fmaxf(0.0f, 1.0f - down * down)) + disc * fmaxf(0.0f, down);
    case LampShape::Cobra:
    case LampShape::Cone:
    case LampShape::Flat: break;
    }
    return disc * down;
}

/// Radiance of the lamp's glass seen along -out (leaving it along unit `out`): the intensity
/// towards `out` over the glass's projected area, so that the glass seen from afar carries the
/// point's intensity.
URBIS_HD inline Vec3f lampGlassRadiance(const LampEmitter& lamp, Vec3f out) {
    const float area = lampGlassProjectedArea(lamp, out);
    return area > 0.0f ? lampIntensity(lamp, out) / area : Vec3f{};
}

/// The lamp seen from `from`: the unit direction to it, the irradiance it sends there across a
/// surface facing it (`radiance`, with pdf 1: a delta light) and the distance its shadow ray
/// runs, which stops at the glass (LampEmitter::clearance). False where nothing reaches `from`.
URBIS_HD inline bool sampleLampLight(const LampEmitter& lamp, Vec3f from, Vec3f& dir, Vec3f& radiance, float& distance,
                                     float& pdf) {
    const Vec3f toLamp = lamp.position - from;
    const float d2 = dot(toLamp, toLamp), d = sqrtf(d2);
    if (!(d > lamp.clearance)) return false;
    dir = toLamp / d;
    radiance = lampIntensity(lamp, -dir) / d2;
    distance = d - lamp.clearance;
    pdf = 1.0f;
    return maxComponent(radiance) > 0.0f;
}

/// Bounds of a lamp for the light BVH: its point, its flux `phi`, and its directions: below the
/// horizontal about straight down for a full-cutoff head, every direction for a globe or lantern
/// (pbrt-v4's PointLight: theta_o = pi, theta_e = pi / 2).
URBIS_HD inline LightBounds lampLightBounds(const LampEmitter& lamp, float phi) {
    LightBounds b;
    b.bounds = {lamp.position, lamp.position};
    b.axis = {0.0f, -1.0f, 0.0f};
    b.cosThetaO = lampCutoffExponent(lamp.shape) > 0.0f ? 1.0f : -1.0f;
    b.cosThetaE = 0.0f;
    b.phi = phi;
    return b;
}

} // namespace urbis
