// Closest-hit and shadow queries over every primitive kind of a scene (host+device): the one place
// where kinds are dispatched, so new kinds join here without touching the integrators.
#pragma once

#include "scene/scene_view.h"

namespace urbis {

enum class SurfaceKind : uint32_t { None, Triangle, Ground };

/// What the integrator needs of a hit: where, which way the surface faces, what it is made of.
struct SurfaceHit {
    SurfaceKind kind = SurfaceKind::None;
    float t = 0;
    Vec3f normal;          ///< unit geometric normal, facing against the ray
    uint32_t material = 0;
    uint32_t object = 0;   ///< 0 for the ground, building index + 1 otherwise
    URBIS_HD bool valid() const { return kind != SurfaceKind::None; }
};

/// The closest surface along `ray` within (tmin, tmax).
URBIS_HD inline SurfaceHit intersectScene(const SceneView& scene, Ray ray) {
    SurfaceHit out;
    Hit hit = intersectClosest(scene.geometry, ray);
    if (hit.valid()) {
        const Triangle& tri = scene.geometry.triangles[hit.prim];
        out = {SurfaceKind::Triangle, hit.t, normalize(cross(tri.p1 - tri.p0, tri.p2 - tri.p0)),
               scene.triangleInfo[hit.prim].material, scene.triangleInfo[hit.prim].object};
        ray.tmax = hit.t;
    }
    float tGround = scene.ground.intersect(ray);
    if (tGround > 0.0f) out = {SurfaceKind::Ground, tGround, Vec3f{0, 1, 0}, scene.ground.material, 0};
    if (out.valid() && dot(out.normal, ray.dir) > 0.0f) out.normal = -out.normal;
    return out;
}

/// Whether anything blocks `ray` within (tmin, tmax).
URBIS_HD inline bool occludedScene(const SceneView& scene, const Ray& ray) {
    return scene.ground.intersect(ray) > 0.0f || occluded(scene.geometry, ray);
}

} // namespace urbis
