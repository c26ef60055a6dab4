// A planet's cloud shell (host+device): the scene's cloud layer wrapped around a planet, between
// `bottom` and `bottom + thickness` metres above its sea level. The density is the flat layer's
// (media/cloud_density.h) read at a point's planet-fixed position, so the clouds stay put as the
// camera moves, with the coverage field mapped triplanarly as the planet's heightfield is
// (scene/planet_record.h: triplanarWeights), and the altitude profile of the point's height above the sea. The
// tracking (media/cloud_tracking.h) walks the ray's pieces inside the shell under one majorant.
#pragma once

#include "media/cloud_density.h"
#include "scene/planet_record.h"

namespace urbis {

/// The scene's planet, or null in a city.
URBIS_HD inline const PlanetRecord* scenePlanet(const SceneView& scene) {
    return hasFeatures(scene.features, kKindFeature<PlanetRecord>) && scene.planets.size ? &scene.planets[0] : nullptr;
}

/// The planet-fixed position (metres from the planet's centre, y through the north pole) of the world
/// point `p`. In float: 0.5 m at Earth's radius, a two-hundredth of a shape noise texel.
URBIS_HD inline Vec3f planetFixedPosition(const PlanetRecord& pl, Vec3f p) {
    const Vec3f fromCentre = p + pl.up * pl.centreDistance;
    return {dot(pl.planetFromWorld[0], fromCentre), dot(pl.planetFromWorld[1], fromCentre),
            dot(pl.planetFromWorld[2], fromCentre)};
}

/// The coverage field over the sphere: the blend of its three planar projections (yz, zx, xy) of the
/// planet-fixed position `q` by the planet's triplanar weights, so no projection is read where it
/// stretches. Never above the largest of the three, so the field's majorants still bound it.
URBIS_HD inline float cloudShellCoverage(const CloudLayer& layer, ArrayView<float> coverage, Vec3f q) {
    const Vec3f n = normalize(q);
    const Vec3f w = triplanarWeights(n);
    float sum = 0.0f;
    for (int k = 0; k < 3; ++k)
        if (w[k] > 0.0f) sum += w[k] * cloudCoverageAt(layer, coverage, q[(k + 1) % 3], q[(k + 2) % 3]);
    return sum;
}

/// Extinction (per metre) of the cloud shell of `layer` around `pl` at the world point `p`; the
/// shell does not fade (the flat layer's radius is the flat world's horizon). Never above
/// layer.density, the shell's majorant.
URBIS_HD inline float cloudShellDensity(const CloudLayer& layer, const CloudTables& tables, const PlanetRecord& pl, Vec3f p) {
    const float h = (planetAltitude(pl, p) - pl.seaLevel - layer.bottom) / layer.thickness;
    if (!(h > 0.0f && h < 1.0f)) return 0.0f;
    const Vec3f q = planetFixedPosition(pl, p) - layer.wind;
    return cloudDensityOfCoverage(layer, tables, q, h, cloudShellCoverage(layer, tables.coverage, q));
}

/// The parts of the ray `origin` + t `dir` (unit, world), t in [0, tmax], inside the shell: at most two
/// (in and out where it passes below the shell's bottom). Returns how many, in order along the ray.
URBIS_HD inline uint32_t clipToCloudShell(const CloudLayer& layer, const PlanetRecord& pl, Vec3f origin, Vec3f dir,
                                          float tmax, float t0[2], float t1[2]) {
    float outNear, outFar, inNear, inFar;
    const float bottom = pl.seaLevel + layer.bottom;
    if (!planetSphereHits(pl, origin, dir, bottom + layer.thickness, outNear, outFar)) return 0;
    uint32_t n = 0;
    const auto add = [&](float a, float b) {
        a = fmaxf(a, 0.0f);
        b = fminf(b, tmax);
        if (a < b) {
            t0[n] = a;
            t1[n] = b;
            ++n;
        }
    };
    if (planetSphereHits(pl, origin, dir, bottom, inNear, inFar)) {
        add(outNear, inNear);
        add(inFar, outFar);
    } else {
        add(outNear, outFar);
    }
    return n;
}

} // namespace urbis
