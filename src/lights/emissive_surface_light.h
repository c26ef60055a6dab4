// Emitting surfaces as area lights (host+device): a point uniform over the surface's area (a
// triangle picked in proportion to its area, then a uniform point on it), converted to solid angle
// at the shading point (pdf = distance^2 / (|cos| area), Veach 1997, section 4.2).
#pragma once

#include "geometry/surface_hit.h"
#include "lights/light_build.h"
#include "lights/light_bvh_build.h"
#include "lights/light_sample.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene_view.h"

#include <vector>

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

/// The light of the emitting triangle `triangle` (index into SceneView::triangles), or kNoLight if
/// its emission is not light-sampled: a binary search of SceneView::emitterTriangles.
URBIS_HD inline uint32_t lightOfTriangle(const SceneView& scene, uint32_t triangle) {
    const ArrayView<EmitterTriangle>& emitters = scene.emitterTriangles;
    uint32_t lo = 0, hi = emitters.size;
    while (lo < hi) {
        const uint32_t mid = (lo + hi) / 2;
        if (emitters[mid].triangle < triangle) lo = mid + 1;
        else hi = mid;
    }
    return lo < emitters.size && emitters[lo].triangle == triangle ? emitters[lo].light : kNoLight;
}

/// Materials that some primitive other than a triangle can show (host): their emission is not light-sampled.
inline std::vector<bool> materialsOutsideTriangles(const Scene& scene) {
    std::vector<bool> outside(scene.materials.size(), false);
    auto mark = [&](uint32_t m) {
        if (m < outside.size()) outside[m] = true;
    };
    for (const WallRecord& wall : scene.walls) {
        mark(wall.wallMaterial);
        for (uint32_t i = 0; i < uint32_t(FacadeMaterial::Count); ++i) mark(wall.facadeMaterials + i);
    }
    for (const GroundRecord& ground : scene.grounds) mark(ground.material);
    return outside;
}

/// Emitting triangles as a light kind, one light per triangle. Triangles emit through it
/// (KindIntersector<Triangle>::Emitter): BSDF sampling finds them too, so MIS weighs them.
struct EmissiveSurfaceLight {
    static constexpr bool kInfinite = false, kMisWeighs = true, kFoundThroughPanes = false;
    static constexpr bool kPickDraw = true, kPointDraws = true;  ///< a triangle, a point on it

    URBIS_HD static bool sample(const SceneView& scene, const LightRecord& light, Vec3f from, float u0, float u1,
                                float u2, LightSample& s) {
        const EmissiveSurface& surface = scene.emissiveSurfaces[light.index];
        s.radiance = surface.emission;
        return sampleEmissiveSurface(scene.triangleLights.data, surface, from, u0, u1, u2, s.dir, s.distance, s.pdf);
    }
    URBIS_HD static float pdf(const SceneView& scene, const LightRecord& light, Vec3f, Vec3f, float distance,
                              float cosLight) {
        return emissiveSurfacePdf(scene.emissiveSurfaces[light.index], distance, cosLight);
    }
    /// Both sides emit: a side by u4, a cosine-distributed direction about it (flux 2 pi A L).
    URBIS_HD static bool emitPhoton(const SceneView& scene, const LightRecord& light, const PhotonNumbers& u,
                                    SampleStream& rng, float scale, EmittedPhoton& out) {
        const EmissiveSurface& surface = scene.emissiveSurfaces[light.index];
        const TriangleLight& tri = pickTriangle(scene.triangleLights.data, surface, u.u3);
        const Vec2f b = sampleUniformTriangle(u.u1, u.u2);
        const Vec3f e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
        const Vec3f n = normalize(cross(e1, e2)) * (u.u4 < 0.5f ? 1.0f : -1.0f);
        const Vec3f p = tri.p0 + e1 * b.x + e2 * b.y;
        const float v1 = rng.draw(), v2 = rng.draw();
        out.ray = Ray{p + n * 1e-3f, Frame::fromZ(n).toWorld(sampleCosineHemisphere(v1, v2))};
        out.power = surface.emission * (2.0f * kPi * surface.area * scale);
        return true;
    }
    /// A triangle's emission, light-sampled where the list holds emitters.
    URBIS_HD static EmissionAtHit emittedAt(const SceneView& scene, const SurfaceHit&, const Material& material, const Ray&,
                                            Vec3f) {
        if (!(maxComponent(material.emission) > 0.0f)) return {};
        return {material.emission, scene.emitterTriangles.size > 0};
    }
    URBIS_HD static uint32_t lightAt(const SceneView& scene, const SurfaceHit& hit) { return lightOfTriangle(scene, hit.index); }

    /// One light per emitting triangle (in triangle order, so emitterTriangles is sorted), of power
    /// 2 pi A L (a two-sided Lambertian emitter): a light of one triangle has bounds the size of a
    /// lamp's head or a window, which is what lets the light BVH tell near emitters from far ones
    /// (docs/lights.md § Emitting triangles). A material that a wall or the ground also shows is left out.
    static void addLights(LightListBuilder& b) {
        if (!b.options.surfaces) return;
        Scene& scene = b.scene;
        const std::vector<bool> outside = materialsOutsideTriangles(scene);
        for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
            const uint32_t m = scene.triangleInfo[i].material;
            if (m >= scene.materials.size() || outside[m] || !(maxComponent(scene.materials[m].emission) > 0.0f)) continue;
            const Triangle& t = scene.triangles[i];
            const double area = 0.5 * double(length(cross(t.p1 - t.p0, t.p2 - t.p0)));
            if (!(area > 0)) continue;
            const Vec3f emission = scene.materials[m].emission;
            const uint32_t light = b.add(kLightKindOf<EmissiveSurfaceLight>, uint32_t(scene.emissiveSurfaces.size()),
                                         float(2.0 * kPi * area * luminance(emission)));
            scene.emitterTriangles.push_back({i, light});
            scene.emissiveSurfaces.push_back({emission, uint32_t(scene.triangleLights.size()), 1, float(area)});
            scene.triangleLights.push_back(TriangleLight{t.p0, t.p1, t.p2, 1.0f});
        }
    }
    /// Its triangles' box and the cone of their normals, emitting over the hemisphere (theta_e = pi / 2)
    /// of both sides.
    static LightBounds bounds(const Scene& scene, const LightRecord& light) {
        const EmissiveSurface& surface = scene.emissiveSurfaces[light.index];
        LightBounds out;
        for (uint32_t i = 0; i < surface.triangleCount; ++i) {
            const TriangleLight& t = scene.triangleLights[surface.firstTriangle + i];
            LightBounds one;
            one.bounds.extend(t.p0);
            one.bounds.extend(t.p1);
            one.bounds.extend(t.p2);
            one.axis = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
            one.cosThetaO = 1;
            one.cosThetaE = 0;
            one.twoSided = true;
            one.phi = 1;  // any non-zero power: the union only needs the geometry
            out = unionLightBounds(out, one);
        }
        out.phi = light.power;
        return out;
    }
    static float photonFlux(const SceneView&, const LightRecord& light, float) { return light.power; }
};

} // namespace urbis
