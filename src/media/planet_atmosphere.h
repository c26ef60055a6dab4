// The atmosphere around a whole planet (host+device): the city's medium and tables (Hillaire 2020,
// docs/atmosphere.md) with the ground sphere at the planet's sea level, evaluated along rays in the
// planet's camera-relative frame (scene/planet_record.h) instead of from the world's origin. From
// orbit a ray may cross the shell for thousands of kilometres, so a segment is marched
// (Hillaire's per-pixel ray march, § 5.1) rather than taken in closed form at one middle height as
// the city's aerial perspective is; each step's Rayleigh and aerosol columns are still the closed form
// of an exponential layer between the step's end heights (layerColumn), so a step of kilometres
// through a 1.2 km aerosol layer is integrated exactly along its height change.
#pragma once

#include "media/aerial_perspective.h"
#include "media/cloud_shell.h"

namespace urbis {

/// Steps of one segment's march.
inline constexpr uint32_t kPlanetAtmosphereSteps = 32;

/// Height (km) of the world point `p` above the atmosphere's ground sphere (the planet's sea level).
URBIS_HD inline float planetAtmosphereHeight(const PlanetRecord& pl, Vec3f p) {
    return (planetAltitude(pl, p) - pl.seaLevel) * 1e-3f;
}

/// Transmittance from the world point `p` along the unit direction `dir` to the top of the
/// atmosphere, zero where the sea-level sphere is in the way (the planet's shadow).
URBIS_HD inline Vec3f planetTransmittanceToTop(const SceneView& scene, const PlanetRecord& pl, Vec3f p, Vec3f dir) {
    const Atmosphere& a = scene.sky.atmosphere;
    const float r = a.bottomRadius + fmaxf(planetAtmosphereHeight(pl, p), 1e-3f);
    return transmittanceToTop(a, scene.transmittanceLut, r, dot(planetZenithOf(pl, p), dir));
}

/// What the atmosphere does along `origin` + s `dir` (unit, world) for s in [0, `length`] metres
/// (any length: the march covers only the part inside the atmosphere's top sphere). Every point is
/// taken as lit by the sun where the sea-level sphere does not hide it (no terrain shadows in the air).
URBIS_HD inline SegmentMedium planetAtmosphereSegment(const SceneView& scene, const PlanetRecord& pl, Vec3f origin,
                                                      Vec3f dir, float length) {
    const Atmosphere& a = scene.sky.atmosphere;
    SegmentMedium m;
    float near, far;
    const float top = pl.seaLevel + (a.topRadius - a.bottomRadius) * 1e3f;
    if (!planetSphereHits(pl, origin, dir, top, near, far)) return m;
    const float s0 = fmaxf(near, 0.0f), s1 = fminf(far, length);
    if (!(s1 > s0)) return m;
    const float ds = (s1 - s0) / float(kPlanetAtmosphereSteps), dsKm = ds * 1e-3f;
    const float cosTheta = dot(dir, a.sunDirection);
    const float phaseR = rayleighPhase(cosTheta), phaseM = miePhase(a.mieG, cosTheta);
    const float mieExtinction = a.mieScattering + a.mieAbsorption;
    Vec3f throughput{1, 1, 1}, radiance;
    float h0 = fmaxf(planetAtmosphereHeight(pl, origin + dir * s0), 0.0f);
    for (uint32_t i = 0; i < kPlanetAtmosphereSteps; ++i) {
        const float h1 = fmaxf(planetAtmosphereHeight(pl, origin + dir * (s0 + float(i + 1) * ds)), 0.0f);
        const float dy = (h1 - h0) / dsKm;
        const float rayleigh = layerColumn(h0, dy, dsKm, a.rayleighScaleHeight);
        const float mie = layerColumn(h0, dy, dsKm, a.mieScaleHeight);
        const Vec3f middle = origin + dir * (s0 + (float(i) + 0.5f) * ds);
        const float hm = 0.5f * (h0 + h1);
        const Vec3f rayleighColumn = a.rayleighScattering * rayleigh;
        const float mieColumn = a.mieScattering * mie;
        const Vec3f depth = rayleighColumn + a.ozoneAbsorption * (ozoneDensity(a, hm) * dsKm) +
                            Vec3f{1, 1, 1} * (mieExtinction * mie);
        const Vec3f stepT{expf(-depth.x), expf(-depth.y), expf(-depth.z)};
        const float r = a.bottomRadius + hm, muSun = dot(planetZenithOf(pl, middle), a.sunDirection);
        const Vec3f sunT = transmittanceToTop(a, scene.transmittanceLut, r, muSun);
        const Vec3f psi = multiScattering(a, scene.multiScatteringLut, r, muSun);
        const Vec3f single = (rayleighColumn * phaseR + Vec3f{1, 1, 1} * (mieColumn * phaseM)) * sunT;
        const Vec3f multiple = (rayleighColumn + Vec3f{1, 1, 1} * mieColumn) * psi;
        // The step's source spread along it as its extinction weighs it: (1 - T) / tau per channel.
        Vec3f spread;
        for (int c = 0; c < 3; ++c) spread[c] = depth[c] > 1e-4f ? (1.0f - stepT[c]) / depth[c] : 1.0f - 0.5f * depth[c];
        radiance += throughput * (single + multiple) * spread;
        throughput *= stepT;
        h0 = h1;
    }
    m.transmittance = throughput;
    m.inScattered = radiance * a.solarIrradiance;
    return m;
}

/// The sky's radiance along a ray from the world point `origin` in the unit direction `dir` that
/// meets no surface: the light the atmosphere scatters along it.
URBIS_HD inline Vec3f planetSkyRadiance(const SceneView& scene, const PlanetRecord& pl, Vec3f origin, Vec3f dir) {
    return planetAtmosphereSegment(scene, pl, origin, dir, 3.0e38f).inScattered;
}

/// Transmittance of the atmosphere from the world point `p` towards the sun or the moon in the unit
/// direction `dir`: one in a city, whose disks' radiance already holds the transmittance from the
/// world's origin (buildAtmosphere); around a planet, whose disks hold what arrives at the top.
URBIS_HD inline Vec3f diskTransmittanceFrom(const SceneView& scene, Vec3f p, Vec3f dir) {
    const PlanetRecord* pl = scenePlanet(scene);
    if (!pl || scene.sky.model != SkyModel::Atmosphere) return {1, 1, 1};
    return planetTransmittanceToTop(scene, *pl, p, dir);
}

/// Applies the atmosphere to the path segment `ray` (world; its direction of any length) up to its
/// parameter `t`, as applyAerialPerspective does: around a planet by the march above.
URBIS_HD inline void applySegmentMedium(const SceneView& scene, const Ray& ray, float t, Vec3f& throughput,
                                        Vec3f& radiance) {
    const PlanetRecord* pl = scenePlanet(scene);
    if (!pl) return applyAerialPerspective(scene, ray, t, throughput, radiance);
    if (!hasAerialPerspective(scene.sky)) return;
    const float len = length(ray.dir);
    const SegmentMedium m = planetAtmosphereSegment(scene, *pl, ray.origin, ray.dir / len, t * len);
    radiance += throughput * m.inScattered;
    throughput *= m.transmittance;
}

} // namespace urbis
