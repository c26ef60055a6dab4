// The forest kind's intersector for the leaf dispatch (host+device): the cell walk over its hashed
// trees (forest_intersect.h), each shaded as the tree kind shades a mapped tree.
#pragma once

#include "geometry/forest_intersect.h"
#include "geometry/tree_kind.h"

namespace urbis {

template <>
struct KindIntersector<ForestRecord> {
    /// A forest on the terrain reads its heights (SceneView::terrainData) for its trees' feet.
    static constexpr bool kReadsScene = true;
    URBIS_HD static ForestGround groundOf(const SceneView& scene, const ForestRecord& f) {
        return f.onTerrain && scene.terrains.size > 0 ? ForestGround{&scene.terrains[0], scene.terrainData.data} : ForestGround{};
    }
    /// The hit tree's cell travels in PrimHit's u and v (integers, exact in a float up to 2^24 cells).
    URBIS_HD static bool intersect(const SceneView& scene, const ForestRecord& f, const TraceRay& tr, Ray& ray, PrimHit& hit,
                                   bool anyHit) {
        float t;
        int32_t cell[2];
        if (!intersectForest(f, groundOf(scene, f), ray, tr.bvh.invDir, anyHit, t, cell)) return false;
        hit.t = t;
        hit.u = float(cell[0]);
        hit.v = float(cell[1]);
        ray.tmax = t;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView& scene, uint32_t index, const ForestRecord& f, const PrimHit& hit,
                                       const Ray& ray) {
        TreeRecord tree;
        forestTreeAt(f, groundOf(scene, f), int32_t(hit.u), int32_t(hit.v), tree);
        return KindIntersector<TreeRecord>::surface(scene, index, tree, hit, ray);
    }
};

} // namespace urbis
