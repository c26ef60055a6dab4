// Ray/planet intersection (host+device): the ocean as a sphere at sea level, met analytically, and
// the terrain ray marched conservatively inside the shell that holds it (Hart 1996, "Sphere tracing":
// steps of the signed altitude over its Lipschitz bound never pass the surface), then the surface's
// normal, and its material by altitude, latitude and slope.
#pragma once

#include "geometry/planet_terrain.h"
#include "geometry/surface_hit.h"

namespace urbis {

/// Steps of one march at most; a march that runs out reports a hit where it stopped (never a hole).
inline constexpr uint32_t kPlanetMaxSteps = 1024;
/// Metres: the march's tolerance near the camera, above the float error of a height (about 1e-7 of
/// the amplitude, a millimetre for 8 km).
inline constexpr float kPlanetEpsilon = 5e-3f;

/// The march's tolerance at the world point `p` (metres): a twentieth of a pixel's footprint there,
/// plus kPlanetEpsilon.
URBIS_HD inline float planetEpsilon(const PlanetRecord& pl, Vec3f p) {
    return kPlanetEpsilon + 0.05f * pl.lodAngle * length(p);
}

/// What a march found: where and in how many steps.
struct PlanetMarch {
    bool hit = false;
    float s = 0;          ///< metres along the ray
    uint32_t steps = 0;
};

/// Marches the terrain along `origin` + s `dir` (unit) from s = `s0` to `s1` (metres). A ray that
/// starts on the surface (a bounce or a shadow ray: s0 = 0 within twice the tolerance of it) first
/// leaves it with steps of at least the tolerance, and counts as blocked only if it sinks below it
/// meanwhile; a ray from anywhere else (s0 = 0 farther off, or s0 > 0: from outside the shell) is
/// marched from the start.
URBIS_HD inline PlanetMarch marchPlanetTerrain(const PlanetRecord& pl, Vec3f origin, Vec3f dir, float s0, float s1) {
    PlanetMarch m;
    const float invLipschitz = 1.0f / pl.lipschitz;
    float s = s0;
    bool armed = s0 > 0.0f;
    for (; m.steps < kPlanetMaxSteps; ++m.steps) {
        const Vec3f p = origin + dir * s;
        const float f = planetTerrainDistance(pl, p), eps = planetEpsilon(pl, p);
        if (!armed) armed = f >= 2.0f * eps;
        if (armed ? f < eps : f < -eps) {
            m.hit = true;
            m.s = s;
            return m;
        }
        s += armed ? f * invLipschitz : fmaxf(f * invLipschitz, eps);
        if (s > s1) return m;
    }
    m.hit = true;
    m.s = s;
    return m;
}

/// Whether `ray` meets the planet with ray.tmin < t < ray.tmax: then t (units of |ray.dir|) and
/// whether it is the ocean's surface.
URBIS_HD inline bool intersectPlanet(const PlanetRecord& pl, const Ray& ray, float& t, bool& ocean) {
    const float len = length(ray.dir);
    const Vec3f o = ray.origin, d = ray.dir * (1.0f / len);
    const float sMin = ray.tmin * len, sMax = ray.tmax * len;
    float sEnd = sMax, near, far;
    ocean = false;
    // A ray leaving the sea's surface upwards cannot meet that sphere again: its roots are rounding.
    const bool leavesSea = fabsf(planetAltitude(pl, o) - pl.seaLevel) < 2.0f * planetEpsilon(pl, o) &&
                           dot(d, planetZenithOf(pl, o)) >= 0.0f;
    if (!leavesSea && planetSphereHits(pl, o, d, pl.seaLevel, near, far)) {
        const float s = near > sMin ? near : far;
        if (s > sMin && s < sEnd) {
            sEnd = s;
            ocean = true;
        }
    }
    if (planetSphereHits(pl, o, d, fmaxf(pl.amplitude, pl.seaLevel), near, far) && far > sMin) {
        const PlanetMarch m = marchPlanetTerrain(pl, o, d, fmaxf(near, sMin), fminf(far, sEnd));
        // Within the march's tolerance above terrain under the sea, the sea is what the ray meets.
        Vec3f zenith;
        if (m.hit && m.s < sEnd && !(ocean && planetHeight(pl, o + d * m.s, zenith) < pl.seaLevel)) {
            t = m.s / len;
            ocean = false;
            return true;
        }
    }
    if (ocean) t = sEnd / len;
    return ocean;
}

/// Unit normal of the terrain at the world point `p`: the gradient of the signed altitude by the
/// tetrahedral central difference (four evaluations), over a step of twice the march's tolerance.
URBIS_HD inline Vec3f planetTerrainNormal(const PlanetRecord& pl, Vec3f p) {
    const float h = 2.0f * planetEpsilon(pl, p) + 0.02f;
    const Vec3f k0{1, -1, -1}, k1{-1, -1, 1}, k2{-1, 1, -1}, k3{1, 1, 1};
    const Vec3f g = k0 * planetTerrainDistance(pl, p + k0 * h) + k1 * planetTerrainDistance(pl, p + k1 * h) +
                    k2 * planetTerrainDistance(pl, p + k2 * h) + k3 * planetTerrainDistance(pl, p + k3 * h);
    return normalize(g);
}

/// The material of terrain at `height` metres above the base sphere with the unit planet-fixed
/// zenith `zenith` (its y: the sine of the latitude) and `slope` (1 - cos of the surface's tilt):
/// snow above a snow line that falls from 0.6 amplitude at the equator to the sea at the poles,
/// rock on steep slopes and high ground, sand on beaches, vegetation elsewhere.
URBIS_HD inline PlanetMaterial planetMaterialAt(const PlanetRecord& pl, float height, Vec3f zenith, float slope) {
    const float above = height - pl.seaLevel, sinLat = fabsf(zenith.y);
    const float snowLine = 0.6f * pl.amplitude * (1.0f - sinLat * sinLat * sinLat * sinLat);
    if (above > snowLine && slope < 0.3f) return PlanetMaterial::Snow;
    if (slope > 0.25f || above > 0.35f * pl.amplitude) return PlanetMaterial::Rock;
    if (above < 0.006f * pl.amplitude) return PlanetMaterial::Sand;
    return PlanetMaterial::Vegetation;
}

template <>
struct KindIntersector<PlanetRecord> {
    URBIS_HD static bool intersect(const PlanetRecord& pl, const TraceRay&, Ray& ray, PrimHit& hit, bool) {
        float t;
        bool ocean;
        if (!intersectPlanet(pl, ray, t, ocean)) return false;
        hit.t = t;
        hit.material = ocean ? 1u : 0u;
        ray.tmax = t;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView&, uint32_t, const PlanetRecord& pl, const PrimHit& hit,
                                       const Ray& ray) {
        const Vec3f p = pointAt(ray, hit.t);
        const Vec3f up = planetZenithOf(pl, p);
        Vec3f normal = up;
        PlanetMaterial material = PlanetMaterial::Ocean;
        if (hit.material == 0u) {
            normal = planetTerrainNormal(pl, p);
            Vec3f zenith;
            const float height = planetHeight(pl, p, zenith);
            material = planetMaterialAt(pl, height, zenith, 1.0f - dot(normal, up));
        }
        const Vec3f tangent = cross(normal, fabsf(normal.x) < 0.9f ? Vec3f{1, 0, 0} : Vec3f{0, 0, 1});
        return {kNoPrimKind, hit.t, p, normal, tangent, {0, 0}, pl.materials + uint32_t(material), 0, SurfacePart::Whole};
    }
};

} // namespace urbis
