// The tree kind's intersector for the leaf dispatch (host+device): the sphere-traced tree.
#pragma once

#include "geometry/surface_hit.h"
#include "geometry/tree_intersect.h"
#include "math/constants.h"

namespace urbis {

template <>
struct KindIntersector<TreeRecord> {
    URBIS_HD static bool intersect(const TreeRecord& tree, const TraceRay& tr, Ray& ray, PrimHit& hit, bool) {
        float t;
        if (!intersectTree(tree, treeShapeOf(tree), ray, tr.bvh.invDir, t)) return false;
        hit.t = t;
        ray.tmax = t;
        return true;
    }
    /// The normal is the distance's gradient by central differences (5 mm); uv: the hit's height
    /// above the foot and its angle around the trunk (turns).
    URBIS_HD static SurfaceHit surface(const SceneView&, uint32_t, const TreeRecord& tree, const PrimHit& hit,
                                       const Ray& ray) {
        const TreeShapeParams s = treeShapeOf(tree);
        const Vec3f p = pointAt(ray, hit.t), q = p - tree.base;
        constexpr float h = 5e-3f;
        Vec3f g{treeDistance(s, q + Vec3f{h, 0, 0}) - treeDistance(s, q - Vec3f{h, 0, 0}),
                treeDistance(s, q + Vec3f{0, h, 0}) - treeDistance(s, q - Vec3f{0, h, 0}),
                treeDistance(s, q + Vec3f{0, 0, h}) - treeDistance(s, q - Vec3f{0, 0, h})};
        if (!(dot(g, g) > 0.0f)) g = -ray.dir;
        const Vec3f normal = normalize(g);
        const Vec3f around = cross(Vec3f{0, 1, 0}, normal);
        const Vec3f tangent = dot(around, around) > 1e-12f ? around : Vec3f{1, 0, 0};
        const SurfacePart part = treePartAt(s, q);
        const uint32_t material = tree.material + uint32_t(part == SurfacePart::TreeCrown ? TreeMaterial::Leaves : TreeMaterial::Bark);
        const Vec2f uv{q.y, atan2f(q.z, q.x) * (0.5f / kPi) + 0.5f};
        return {kNoPrimKind, hit.t, p, normal, tangent, uv, material, tree.object, part};
    }
};

} // namespace urbis
