#include "scene/wide_triangle_scene_build.h"

#include "accel/wide_leaf_groups.h"

#include <tbb/parallel_for.h>

namespace urbis {

WideTriangleScene buildWideTriangleScene(const std::vector<Triangle>& triangles, const BvhBuildOptions& options) {
    WideTriangleScene scene;
    std::vector<Bounds3f> bounds(triangles.size());
    tbb::parallel_for(size_t(0), triangles.size(), [&](size_t i) { bounds[i] = primBounds(triangles[i]); });
    BvhBuildOptions blockOptions = options;
    blockOptions.leafGroupSize = kTriangleBlockWidth;
    scene.bvh = buildWideBvh(bounds, blockOptions);
    scene.triangles.resize(triangles.size());
    tbb::parallel_for(size_t(0), triangles.size(), [&](size_t i) { scene.triangles[i] = triangles[scene.bvh.primOrder[i]]; });
    const std::vector<WideLeafGroup> groups = groupWideLeaves(scene.bvh, kTriangleBlockWidth);
    scene.blocks.resize(groups.size());
    tbb::parallel_for(size_t(0), groups.size(), [&](size_t g) {
        TriangleBlock& block = scene.blocks[g];
        for (int l = 0; l < kTriangleBlockWidth; ++l) {
            const uint32_t prim = groups[g].first + (uint32_t(l) < groups[g].count ? uint32_t(l) : groups[g].count - 1);
            const Triangle& t = scene.triangles[prim];
            const Vec3f p[3] = {t.p0, t.p1, t.p2};
            for (int v = 0; v < 3; ++v)
                for (int axis = 0; axis < 3; ++axis) block.p[v][axis][l] = p[v][axis];
            block.prim[l] = prim;
        }
    });
    return scene;
}

} // namespace urbis
