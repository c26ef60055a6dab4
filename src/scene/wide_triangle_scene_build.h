// A triangle scene over the 8-wide compressed BVH, its leaves packed into TriangleBlocks (host).
#pragma once

#include "accel/wide_bvh_build.h"
#include "scene/triangle_block.h"
#include "scene/triangle_scene_view.h"

#include <vector>

namespace urbis {

/// What a WideTriangleSceneView points at: the wide BVH, the triangles in its primOrder and its
/// leaves' triangles packed kTriangleBlockWidth at a time (the nodes address the blocks).
struct WideTriangleScene {
    WideBvh bvh;
    std::vector<Triangle> triangles;
    std::vector<TriangleBlock> blocks;

    WideTriangleSceneView view() const { return {bvh.nodes.data(), blocks.data(), triangles.data(), uint32_t(triangles.size())}; }
};

/// buildWideBvh over the triangles' bounds (`options` as there, but with the SAH counting blocks:
/// leafGroupSize = kTriangleBlockWidth), the triangles reordered by its
/// primOrder, each leaf split into blocks of up to kTriangleBlockWidth (groupWideLeaves), a short
/// block repeating its last triangle. Deterministic for any thread count.
WideTriangleScene buildWideTriangleScene(const std::vector<Triangle>& triangles, const BvhBuildOptions& options = {});

} // namespace urbis
