// The sky as an environment light (host+device): its radiance (analytic or the atmosphere's), and directions importance-sampled
// from a piecewise-constant table of that radiance over an equal-area map of the sphere (pbrt-v3
// InfiniteAreaLight's method; the table is built once per scene by buildLights). Map (Lambert's
// cylindrical equal-area projection): u = phi / 2 pi with phi the azimuth from +x towards +z,
// v = (1 - cos theta) / 2 with theta from +y (up). Every cell covers the same solid angle, so the
// map's Jacobian is the constant 4 pi: no sin theta and no acos per ray, which keeps the GPU's
// render kernel smaller (docs/gpu_notes.md § Instruction cache).
#pragma once

#include "lights/light_build.h"
#include "lights/light_sample.h"
#include "math/piecewise_constant.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "media/atmosphere_lut.h"
#include "media/planet_atmosphere.h"
#include "scene/scene_view.h"

#include <vector>

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

/// The sky's importance table as its view: empty where the sky is not in the list.
URBIS_HD inline PiecewiseConstant2DView skyTableOf(const SceneView& scene) {
    return {scene.skyTable.data, scene.lights.skyNu, scene.lights.skyNv};
}

/// A photon of the sky: a direction of the upper hemisphere, uniform (pdf 1 / 2 pi; the light
/// sampler's table leaves out what MIS compensation removed, so it cannot serve here), through the disk.
URBIS_HD inline EmittedPhoton skyPhoton(const SceneView& scene, float u1, float u2, float u3, float u4) {
    const Vec3f towards = Frame::fromZ(Vec3f{0, 1, 0}).toWorld(directionAtCosine(u1, u2));
    const float r = scene.photons.radius;
    return {rayFromDisk(scene.photons.centre, r, towards, u3, u4), skyRadiance(scene, towards) * (2.0f * kPi * kPi * r * r)};
}

/// Flux of the upper hemisphere of the sky through the disk of a sphere of `radius` (host): pi r^2
/// times the integral of its luminance over the hemisphere (midpoint rule, 64 x 16 directions).
inline float skyHemisphereFlux(const SceneView& scene, float radius) {
    constexpr int kPhi = 64, kCos = 16;
    double sum = 0;
    for (int j = 0; j < kCos; ++j)
        for (int i = 0; i < kPhi; ++i) {
            const float cosTheta = (j + 0.5f) / kCos, phi = 2.0f * kPi * (i + 0.5f) / kPhi;
            const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
            sum += luminance(skyRadiance(scene, Vec3f{sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)}));
        }
    return float(sum * (2.0 * kPi / (kPhi * kCos)) * kPi * radius * radius);
}

/// The sky's luminance table over the equal-area map (every cell the same solid angle), and its
/// integral over the sphere (luminance per solid angle), on the host. With `upperOnly` (an infinite
/// ground plane hides every direction below the horizon from every point above it) the rows below
/// the horizon stay zero. With `compensate`, the table holds only what exceeds the sky's mean
/// luminance (MIS compensation, Karlik et al. 2019; pbrt-v4 ImageInfiniteLight): BSDF sampling
/// already finds the even part well, so light samples go where the sky is brighter than that.
/// Directions of pdf 0 are BSDF sampling's alone, with weight 1: every estimate stays unbiased.
inline std::vector<float> skyLuminanceTable(const SceneView& scene, uint32_t nu, uint32_t nv, bool upperOnly,
                                            bool compensate, double& integral) {
    std::vector<float> func(size_t(nu) * nv, 0.0f);
    const double cell = 4.0 * kPi / (double(nu) * nv);
    const uint32_t rows = upperOnly ? (nv + 1) / 2 : nv;
    double sum = 0;
    for (uint32_t v = 0; v < rows; ++v)
        for (uint32_t u = 0; u < nu; ++u) {
            const Vec2f uv{(float(u) + 0.5f) / float(nu), (float(v) + 0.5f) / float(nv)};
            const float lum = luminance(skyRadiance(scene, skyDirectionFromUv(uv)));
            func[size_t(v) * nu + u] = lum;
            sum += lum;
        }
    const float mean = compensate ? float(sum / (double(rows) * nu)) : 0.0f;
    integral = 0;
    for (uint32_t v = 0; v < rows; ++v)
        for (uint32_t u = 0; u < nu; ++u) {
            float& f = func[size_t(v) * nu + u];
            f = fmaxf(0.0f, f - mean);
            integral += double(f) * cell;
        }
    return func;
}

/// The sky as a light kind: infinite, weighed by MIS (BSDF sampling finds it too).
struct SkyLight {
    static constexpr bool kInfinite = true, kMisWeighs = true, kFoundThroughPanes = false;
    static constexpr bool kPickDraw = false, kPointDraws = true;  ///< a direction from the table: two numbers

    URBIS_HD static bool sample(const SceneView& scene, const LightRecord&, Vec3f, float, float u1, float u2,
                                LightSample& s) {
        s.dir = sampleSkyDirection(skyTableOf(scene), u1, u2, s.pdf);
        s.radiance = skyRadiance(scene, s.dir);
        return s.pdf > 0.0f;
    }
    URBIS_HD static float pdf(const SceneView& scene, const LightRecord&, Vec3f, Vec3f dir, float, float) {
        return skyDirectionPdf(skyTableOf(scene), dir);
    }
    URBIS_HD static bool emitPhoton(const SceneView& scene, const LightRecord&, const PhotonNumbers& u, SampleStream&,
                                    float scale, EmittedPhoton& out) {
        out = skyPhoton(scene, u.u1, u.u2, u.u3, u.u4);
        out.power *= scale;
        return true;
    }
    /// What a ray that meets nothing sees: the sky from `origin` (skyRadianceFrom).
    URBIS_HD static bool escaped(const SceneView& scene, Vec3f origin, Vec3f dir, uint32_t, Vec3f& radiance) {
        radiance = skyRadianceFrom(scene, origin, dir);
        return true;
    }

    /// Adds the sky with its table of options.skyWidth x skyHeight cells and its power, pi r^2 times
    /// the table's integral. Under a bright sun a sky sample takes the place of a sun sample, whose
    /// shadows make most of the noise, and its shadow ray is incoherent: the sky joins only where its
    /// power is at least options.skyMinShare of the sun's and its own together, else it is BSDF
    /// sampling's alone (counted in full, unbiased), as where its table is empty (docs/lights.md § The
    /// light set).
    static void addLights(LightListBuilder& b) {
        const LightBuildOptions& o = b.options;
        if (!o.sky || o.skyWidth == 0 || o.skyHeight == 0) return;
        double integral = 0;
        std::vector<float> func =
            skyLuminanceTable(b.scene.view(), o.skyWidth, o.skyHeight, !b.scene.grounds.empty(), o.compensateSky, integral);
        const double skyPower = double(kPi) * b.radius * b.radius * integral;
        const uint32_t sun = b.scene.lights.firstOfKind[kLightKindOf<SunLight>];
        const double sunPower = sun == kNoLight ? 0.0 : double(b.scene.lightRecords[sun].power);
        if (!(integral > 0 && skyPower >= double(o.skyMinShare) * (skyPower + sunPower))) return;
        b.scene.skyTable = buildPiecewiseConstant2D(func, o.skyWidth, o.skyHeight);
        b.scene.lights.skyNu = o.skyWidth;
        b.scene.lights.skyNv = o.skyHeight;
        b.add(kLightKindOf<SkyLight>, 0, float(skyPower));
    }
    static LightBounds bounds(const Scene&, const LightRecord&) { return {}; }
    /// What its photons carry: the upper hemisphere's flux (skyPhoton), not the compensated table's power.
    static float photonFlux(const SceneView& scene, const LightRecord&, float radius) {
        return skyHemisphereFlux(scene, radius);
    }
};

} // namespace urbis
