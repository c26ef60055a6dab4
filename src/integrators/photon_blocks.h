// Blocks of buildings for the photon buffers (host): buildings whose footprints touch (terraced rows,
// a city block's walls) are clustered into one block, up to a block's largest extent, and each cell of
// a ground grid is given to the nearest block, so that every ground point and every building surface
// has one block's buffers (Argudo, Andujar and Patow cluster by the street network; urbis by
// footprints, which also serves scenes without streets). Buildings a gap apart stay apart: the walls
// across a gap face the same way as the block's front at the same angle from its axis, and two
// surfaces on one texel would sum their light. docs/photons.md § Blocks.
#pragma once

#include "scene/photon_view.h"
#include "scene/scene.h"

#include <vector>

namespace urbis {

struct PhotonBlockOptions {
    float gap = 0.5f;            ///< metres: buildings nearer than this (footprint boxes) share a block
    float maxExtent = 160.0f;    ///< metres: a block grows no wider or deeper than this
    float groundReach = 40.0f;   ///< metres: ground further than this from every block has no buffer
    float groundCell = 4.0f;     ///< metres: the ground grid's cell (larger for large cities: at most 2048 a side)
};

/// The blocks of a scene and the maps from buildings and ground cells to them; the blocks carry no
/// memory yet (PhotonBlock::texelOffset == kNoTexels).
struct PhotonBlockSet {
    std::vector<PhotonBlock> blocks;
    std::vector<uint32_t> blockOfObject;   ///< by building object id - 1
    std::vector<uint32_t> groundCells;     ///< row-major over z then x
    uint32_t groundW = 0, groundH = 0;
    Vec2f groundLo;
    float groundCell = 0;
};

/// Clusters the buildings of `scene` (walls and triangles with an object id) into blocks.
/// Deterministic: the same scene gives the same blocks in the same order.
PhotonBlockSet buildPhotonBlocks(const Scene& scene, const PhotonBlockOptions& options = {});

/// The box of every building object (index: object id - 1; empty boxes for ids without surfaces).
std::vector<Bounds3f> buildingBoxes(const Scene& scene);

} // namespace urbis
