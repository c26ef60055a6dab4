// Closest-hit and shadow queries over every primitive kind of a scene (host+device): the one place
// where kinds are dispatched, so new kinds join here without touching the integrators.
#pragma once

#include "geometry/wall_intersect.h"
#include "math/kernel_math.h"
#include "scene/prim_ref.h"
#include "scene/scene_view.h"
#include "scene/surface_part.h"

namespace urbis {

enum class SurfaceKind : uint32_t { None, Triangle, Wall, Ground };

/// What the integrator needs of a hit: where, which way the surface faces, what it is made of.
struct SurfaceHit {
    SurfaceKind kind = SurfaceKind::None;
    float t = 0;
    Vec3f normal;          ///< unit geometric normal, facing against the ray
    uint32_t material = 0;
    uint32_t object = 0;   ///< 0 for the ground, building index + 1 otherwise
    SurfacePart part = SurfacePart::Whole;
    URBIS_HD bool valid() const { return kind != SurfaceKind::None; }
};

/// The triangle hit `prim` (an index into scene.geometry.triangles) as a surface hit.
URBIS_HD inline SurfaceHit triangleSurface(const SceneView& scene, uint32_t prim, float t) {
    const Triangle& tri = scene.geometry.triangles[prim];
    const TriangleInfo info = scene.triangleInfo[prim];
    return {SurfaceKind::Triangle, t, approxNormalize(cross(tri.p1 - tri.p0, tri.p2 - tri.p0)), info.material, info.object,
            SurfacePart(info.part)};
}

/// The ground plane hit at `t` as a surface hit.
URBIS_HD inline SurfaceHit groundSurface(const SceneView& scene, float t) {
    return {SurfaceKind::Ground, t, Vec3f{0, 1, 0}, scene.ground.material, 0, SurfacePart::Whole};
}

/// Closest hit (or with anyHit the first found) over a BVH whose leaves mix kinds
/// (scene.primRefs): triangles are tested where the traversal meets them, walls (each alone in a
/// leaf marked kBvhCostlyLeaf) there too or, with Defer (the GPU's default), when every traversing
/// lane of the warp holds one (traverseBvh). Both find the same hit.
template <bool Defer = URBIS_GPU_CODE>
URBIS_HD inline SurfaceHit traceMixed(const SceneView& scene, Ray& ray, bool anyHit) {
    const BvhRay br(ray);
    const WatertightRay wr(ray, br.invDir);
    Hit hit;
    WallHit wallHit;
    auto testTriangle = [&](uint32_t slot, Ray& r, Hit& h) {
        const uint32_t ref = scene.primRefs[slot];
        float t, u, v;
        if (!intersectTriangle(scene.geometry.triangles[primRefIndex(ref)], r, wr, t, u, v)) return false;
        h = {ref, t, u, v};
        r.tmax = t;
        return true;
    };
    auto testWall = [&](uint32_t slot, Ray& r, Hit& h) {
        const uint32_t ref = scene.primRefs[slot];
        WallHit w;
        if (!intersectWall(scene.walls[primRefIndex(ref)], r, w, anyHit, br.invDir[1])) return false;
        h = {ref, w.t, 0, 0};
        wallHit = w;
        r.tmax = w.t;
        return true;
    };
    traverseBvh<true, Defer>(scene.geometry.nodes, br, ray, hit, anyHit, testTriangle, testWall);
    if (!hit.valid()) return {};
    const uint32_t index = primRefIndex(hit.prim);
    if (primRefKind(hit.prim) == PrimKind::Triangle) return triangleSurface(scene, index, hit.t);
    const WallRecord& wall = scene.walls[index];
    return {SurfaceKind::Wall, hit.t, wallAxisNormal(wall, wallHit.axis), wallHit.material, wall.object, wallHit.part};
}

/// What a scene's BVH holds, where the caller knows it when compiling: the GPU builds one render
/// kernel per layout, each holding only the traversal it runs (docs/gpu_notes.md). Any: decided per
/// call from SceneView::primRefs.
enum class SceneLayout : uint8_t { Any, Mixed, Triangles };

/// The closest surface along `ray` within (tmin, tmax), or with anyHit (a shadow ray) the first
/// one found: then only valid() means anything (blocked). One function for both queries, so that
/// the GPU path tracer inlines the traversal and the wall intersector once: two copies overflowed
/// the H100's instruction cache (docs/gpu_notes.md). `Layout` must match scene.primRefs.
template <SceneLayout Layout = SceneLayout::Any>
URBIS_HD inline SurfaceHit traceScene(const SceneView& scene, Ray ray, bool anyHit) {
    SurfaceHit out;
    // The ground within the ray's whole reach, once: a shadow ray it blocks needs nothing else, and
    // it is in front of whatever the traversal finds closer than the ray's end only if nearer.
    const float tGround = scene.ground.intersect(ray);
    if (anyHit && tGround > 0.0f) return groundSurface(scene, tGround);
    if (Layout == SceneLayout::Any ? scene.primRefs != nullptr : Layout == SceneLayout::Mixed) {
        out = traceMixed(scene, ray, anyHit);
    } else {
        Hit hit = traceTriangles(scene.geometry, ray, anyHit);
        if (hit.valid()) out = triangleSurface(scene, hit.prim, hit.t);
    }
    if (anyHit) return out;
    if (tGround > 0.0f && !(out.valid() && out.t <= tGround)) out = groundSurface(scene, tGround);
    if (out.valid() && fusedDot(out.normal, ray.dir) > 0.0f) out.normal = -out.normal;
    // -0 + 0 is +0: signed zeros differ between a wall's exact axes and its twin's cross products, and
    // the shading frame (Frame::fromZ) branches on the sign of z, so both would sample differently.
    out.normal = out.normal + Vec3f{0.0f, 0.0f, 0.0f};
    return out;
}

/// The closest surface along `ray` within (tmin, tmax).
URBIS_HD inline SurfaceHit intersectScene(const SceneView& scene, Ray ray) { return traceScene(scene, ray, false); }

/// Whether anything blocks `ray` within (tmin, tmax).
URBIS_HD inline bool occludedScene(const SceneView& scene, const Ray& ray) { return traceScene(scene, ray, true).valid(); }

} // namespace urbis
