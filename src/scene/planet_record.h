// A whole planet: the record of the planet kind (host+device POD). A sphere whose surface is a
// triplanar fBm heightfield, oceans at sea level, seen in camera-relative coordinates: the world's
// origin is the camera and its y axis the local zenith there (as for a city), and the planet's
// centre lies centreDistance below it. The host works out, in double, everything whose float form
// would cancel near the surface (the camera's altitude, the noise lattice around the camera), so
// per-ray code handles only offsets from the camera (docs/planets.md § Precision).
#pragma once

#include "math/bounds.h"

#include <cstdint>

namespace urbis {

/// Octaves of the heightfield's fBm at most.
inline constexpr uint32_t kPlanetMaxOctaves = 24;

/// The planet's materials, in this order from PlanetRecord::materials.
enum class PlanetMaterial : uint32_t { Ocean, Sand, Vegetation, Rock, Snow, Count };

struct PlanetRecord {
    Vec3f up{0, 1, 0};             ///< unit world direction from the planet's centre to the camera
    float centreDistance = 0;      ///< metres from the camera to the centre: radius + cameraAltitude
    float cameraAltitude = 0;      ///< metres of the camera above the base sphere (double on the host)
    float radius = 0;              ///< metres: the base sphere the heights are measured from
    float seaLevel = 0;            ///< metres above the base sphere
    float amplitude = 0;           ///< metres: |height| <= amplitude
    float heightScale = 0;         ///< metres per unit of the octaves' sum: amplitude / sum of gain^i
    float lipschitz = 1;           ///< bound of |grad| of the signed altitude above the terrain (planetTerrainLipschitz)
    float lodAngle = 0;            ///< radians: octaves shorter than lodAngle x distance from the camera fade out
    float baseFrequency = 0;       ///< cycles per metre of octave 0
    float gain = 0.5f;             ///< amplitude ratio of successive octaves (frequencies double)
    uint32_t octaves = 0;
    uint32_t seed = 0;
    uint32_t materials = 0;        ///< the first of the PlanetMaterial materials
    Vec3f planetFromWorld[3];      ///< rows: the world's directions in the planet-fixed frame (y: the north pole)
    /// The noise lattice around the camera's point of the base sphere, per octave and planet-fixed
    /// axis: the integer cell (modulo 2^32) and the fraction of the camera point's coordinate
    /// times the octave's frequency, split on the host in double.
    int32_t cell[kPlanetMaxOctaves][3];
    float frac[kPlanetMaxOctaves][3];

    /// Marched (a Lipschitz bound): each is a leaf of its own, deferred on the GPU as walls are.
    static constexpr uint32_t kBvhCost = 64;

    /// World position of the planet's centre.
    URBIS_HD Vec3f centre() const { return up * -centreDistance; }
    /// Radius of the shell that holds every surface, metres.
    URBIS_HD float outerRadius() const { return radius + fmaxf(amplitude, seaLevel); }
};

/// The signed distance (metres) of the world point `p` from the sphere through the camera, along
/// the vertical: |p - centre| - centreDistance, as (2 D p.up + p.p) / (|p - centre| + D), which does
/// not cancel near the camera as the difference of two lengths of 6e6 m would. `toCentre`: |p - centre|.
URBIS_HD inline float radialOffset(const PlanetRecord& pl, Vec3f p, float& toCentre) {
    const float D = pl.centreDistance;
    toCentre = length(p + pl.up * D);
    return (2.0f * D * dot(p, pl.up) + dot(p, p)) / (toCentre + D);
}

/// Triplanar weights of a plane whose normal axis has the component |n_k| of the unit planet-fixed
/// direction: max(|n_k| - kTriplanarCut, 0), normalised by their sum (at least 1/sqrt 3 - cut). Shared
/// by the heightfield (geometry/planet_terrain.h) and the cloud shell's coverage (media/cloud_shell.h).
inline constexpr float kTriplanarCut = 0.3f;

URBIS_HD inline Vec3f triplanarWeights(Vec3f n) {
    const Vec3f w{fmaxf(fabsf(n.x) - kTriplanarCut, 0.0f), fmaxf(fabsf(n.y) - kTriplanarCut, 0.0f),
                  fmaxf(fabsf(n.z) - kTriplanarCut, 0.0f)};
    return w * (1.0f / (w.x + w.y + w.z));
}

/// Altitude (metres) of the world point `p` above the base sphere, precise near the camera.
URBIS_HD inline float planetAltitude(const PlanetRecord& pl, Vec3f p) {
    float toCentre;
    return pl.cameraAltitude + radialOffset(pl, p, toCentre);
}

/// The unit world direction of the point `p` from the planet's centre (its zenith).
URBIS_HD inline Vec3f planetZenithOf(const PlanetRecord& pl, Vec3f p) { return normalize(p + pl.up * pl.centreDistance); }

/// The parameters t of the ray `origin` + t `dir` (`dir` unit, world) on the sphere of radius
/// radius + `height` (metres) around the planet's centre, near <= far; false where it misses. The
/// constant term |o - c|^2 - r^2 is formed as (a - height)(2 radius + height + a) from the origin's
/// altitude a (planetAltitude), and the near root of a ray from outside as c / q (Numerical Recipes
/// § 5.6), so neither cancels at the surface.
URBIS_HD inline bool planetSphereHits(const PlanetRecord& pl, Vec3f origin, Vec3f dir, float height, float& near,
                                     float& far) {
    const float a = planetAltitude(pl, origin);
    const float b = dot(dir, origin) + pl.centreDistance * dot(dir, pl.up);  // dot(dir, origin - centre)
    const float c = (a - height) * (2.0f * pl.radius + height + a);
    const float disc = b * b - c;
    if (disc < 0.0f) return false;
    const float q = b >= 0.0f ? -(b + sqrtf(disc)) : -b + sqrtf(disc);
    const float r0 = q, r1 = q != 0.0f ? c / q : 0.0f;
    near = fminf(r0, r1);
    far = fmaxf(r0, r1);
    return true;
}

/// World bounds of the planet: the box of its outer shell.
inline Bounds3f primBounds(const PlanetRecord& p) {
    const float r = p.outerRadius();
    const Vec3f c = p.centre();
    return {c - Vec3f{r, r, r}, c + Vec3f{r, r, r}};
}

} // namespace urbis
