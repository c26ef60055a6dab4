// Emitting surfaces as area lights (host+device): a point uniform over the surface's area (a
// triangle picked in proportion to its area, then a uniform point on it), converted to solid angle
// at the shading point (pdf = distance^2 / (|cos| area), Veach 1997, section 4.2).
#pragma once

#include "math/sampling.h"
#include "scene/light_records.h"

namespace urbis {

/// Solid-angle pdf of seeing, at `distance`, a point of `surface` whose normal makes cosine
/// `cosLight` with the direction to it (either side: surfaces emit from both).
URBIS_HD inline float emissiveSurfacePdf(const EmissiveSurface& surface, float distance, float cosLight) {
    const float c = fabsf(cosLight);
    return c > 0.0f && surface.area > 0.0f ? distance * distance / (c * surface.area) : 0.0f;
}

/// The triangle of `surface` at share `u` of its area (binary search over TriangleLight::cdf).
URBIS_HD inline const TriangleLight& pickTriangle(const TriangleLight* triangles, const EmissiveSurface& surface, float u) {
    uint32_t lo = surface.firstTriangle, hi = surface.firstTriangle + surface.triangleCount - 1;
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2;
        if (triangles[mid].cdf <= u) lo = mid + 1;
        else hi = mid;
    }
    return triangles[lo];
}

/// A point of `surface` seen from `from`: unit direction, distance and solid-angle pdf. Returns
/// false where the point lies edge-on.
URBIS_HD inline bool sampleEmissiveSurface(const TriangleLight* triangles, const EmissiveSurface& surface, Vec3f from,
                                           float u0, float u1, float u2, Vec3f& dir, float& distance, float& pdf) {
    const TriangleLight& tri = pickTriangle(triangles, surface, u0);
    const Vec2f b = sampleUniformTriangle(u1, u2);
    const Vec3f e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
    const Vec3f toPoint = tri.p0 + e1 * b.x + e2 * b.y - from;
    distance = length(toPoint);
    if (!(distance > 0.0f)) return false;
    dir = toPoint / distance;
    pdf = emissiveSurfacePdf(surface, distance, dot(normalize(cross(e1, e2)), dir));
    return pdf > 0.0f;
}

} // namespace urbis
