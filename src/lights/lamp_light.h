// Street lamps as lights (host+device): a point at the glass's centre whose intensity follows a
// profile by head shape, normalised so that the lamp emits its luminous flux. Lamps are sampled
// as points (pbrt-v4's PointLight with a profile, as its GoniometricLight); the glass, seen by the
// camera or through a mirror, shows the radiance that spreads the same intensity over its
// projected area. A BSDF sample at a diffuse vertex that meets the glass counts nothing, since the
// point's light samples carry the lamp's light there (docs/lights.md § Lamps).
#pragma once

#include "geometry/surface_hit.h"
#include "lights/light_build.h"
#include "lights/light_sample.h"
#include "math/constants.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/lamp_emission.h"
#include "scene/lamp_pieces.h"
#include "scene/light_bounds.h"
#include "scene/scene_view.h"

#include <cmath>

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

/// Lamp `lamp` as a light (host): a point at its glass's centre whose profile carries its luminous
/// flux in the renderer's units (kLuxPerUnit) in its blackbody's colour.
inline LampEmitter lampEmitterOf(const LampRecord& lamp) {
    const LampPiece glass = lampPiece(lamp, 3);
    LampEmitter light;
    light.shape = lamp.shape;
    Vec3f centre = glass.a;
    if (glass.shape == LampPieceShape::Sphere) {
        light.glassRadius = light.clearance = glass.b.x;
    } else if (glass.b.x > 0.0f) {   // a lantern's glass: a frustum up from its bottom
        centre.y += 0.5f * glass.b.x;
        light.glassRadius = glass.b.y + 0.5f * glass.b.z * glass.b.x;
        light.glassHeight = glass.b.x;
        light.clearance = std::hypot(glass.highRadius(), 0.5f * glass.b.x);
    } else {                         // a disc facing down: the shadow ray stops a centimetre short
        light.glassRadius = glass.b.y;
        light.clearance = 0.01f;
    }
    light.position = lamp.worldFromLamp(centre);
    light.intensity = blackbodyRgb(lamp.colourTemperature) * (lamp.luminousFlux / kLuxPerUnit / lampProfileIntegral(lamp.shape));
    return light;
}

/// Street lamps as a light kind, one light per lamp record, at dusk and at night. Lamps emit through
/// it (KindIntersector<LampRecord>::Emitter): their glass. MIS does not weigh it: a point, which
/// BSDF sampling never finds; its glass, found at a scattering vertex, counts nothing.
struct LampLight {
    static constexpr bool kInfinite = false, kMisWeighs = false, kFoundThroughPanes = false;
    static constexpr bool kPickDraw = false, kPointDraws = false;  ///< a point: no numbers

    URBIS_HD static bool sample(const SceneView& scene, const LightRecord& light, Vec3f from, float, float, float,
                                LightSample& s) {
        return sampleLampLight(scene.lampLights[light.index], from, s.dir, s.radiance, s.distance, s.pdf);
    }
    /// A delta light: no direction reaches it by BSDF sampling.
    URBIS_HD static float pdf(const SceneView&, const LightRecord&, Vec3f, Vec3f, float, float) { return 0.0f; }
    /// From the point, a direction uniform over the sphere, weighed by the profile.
    URBIS_HD static bool emitPhoton(const SceneView& scene, const LightRecord& light, const PhotonNumbers& u, SampleStream&,
                                    float scale, EmittedPhoton& out) {
        const LampEmitter& lamp = scene.lampLights[light.index];
        const Vec3f dir = sampleUniformSphere(u.u1, u.u2);
        out.ray = Ray{lamp.position, dir, lamp.clearance};
        out.power = lampIntensity(lamp, dir) * (4.0f * kPi * scale);
        return true;
    }
    /// A lamp's glass where lamps are lights (lampGlassRadiance); else what its material emits.
    URBIS_HD static EmissionAtHit emittedAt(const SceneView& scene, const SurfaceHit& hit, const Material& material,
                                            const Ray&, Vec3f dir) {
        if (hit.part == SurfacePart::LampGlass && scene.lights.first<LampLight>() != kNoLight)
            return {lampGlassRadiance(scene.lampLights[hit.index], -dir), true};
        return {materialEmission(material)};
    }
    URBIS_HD static uint32_t lightAt(const SceneView& scene, const SurfaceHit& hit) {
        return scene.lights.first<LampLight>() + hit.index;
    }

    /// One light per lamp record, in their order, of its luminous flux as power.
    static void addLights(LightListBuilder& b) {
        if (!b.night || !b.options.lamps) return;
        Scene& scene = b.scene;
        for (uint32_t i = 0; i < scene.lamps.size(); ++i) {
            scene.lampLights.push_back(lampEmitterOf(scene.lamps[i]));
            b.add(kLightKindOf<LampLight>, i, scene.lamps[i].luminousFlux / kLuxPerUnit);
        }
    }
    static LightBounds bounds(const Scene& scene, const LightRecord& light) {
        return lampLightBounds(scene.lampLights[light.index], light.power);
    }
    static float photonFlux(const SceneView&, const LightRecord& light, float) { return light.power; }
};

} // namespace urbis
