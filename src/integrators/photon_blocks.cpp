#include "integrators/photon_blocks.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace urbis {

std::vector<Bounds3f> buildingBoxes(const Scene& scene) {
    std::vector<Bounds3f> boxes;
    auto add = [&](uint32_t object, const Bounds3f& b) {
        if (object == 0) return;
        if (boxes.size() < object) boxes.resize(object);
        boxes[object - 1].extend(b);
    };
    for (const WallRecord& wall : scene.walls) add(wall.object, primBounds(wall));
    for (size_t i = 0; i < scene.triangles.size() && i < scene.triangleInfo.size(); ++i)
        add(scene.triangleInfo[i].object, primBounds(scene.triangles[i]));
    return boxes;
}

namespace {

/// Union-find over buildings whose union keeps a block within the largest extent.
struct BlockForest {
    std::vector<uint32_t> parent;
    std::vector<Bounds3f> box;
    uint32_t find(uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void unite(uint32_t a, uint32_t b, float maxExtent) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        Bounds3f joined = box[a];
        joined.extend(box[b]);
        if (joined.hi.x - joined.lo.x > maxExtent || joined.hi.z - joined.lo.z > maxExtent) return;
        if (b < a) std::swap(a, b);   // the lower id is the root: the result does not depend on the order
        parent[b] = a;
        box[a] = joined;
    }
};

/// Distance in (x, z) from point (x, z) to the rectangle of `b`.
float distanceXz(const Bounds3f& b, float x, float z) {
    const float dx = std::max({b.lo.x - x, 0.0f, x - b.hi.x}), dz = std::max({b.lo.z - z, 0.0f, z - b.hi.z});
    return std::sqrt(dx * dx + dz * dz);
}

} // namespace

PhotonBlockSet buildPhotonBlocks(const Scene& scene, const PhotonBlockOptions& options) {
    const std::vector<Bounds3f> boxes = buildingBoxes(scene);
    const uint32_t n = uint32_t(boxes.size());
    BlockForest forest{std::vector<uint32_t>(n), boxes};
    std::iota(forest.parent.begin(), forest.parent.end(), 0u);
    // Sweep along x: candidates are the buildings whose boxes start within the gap of this one's end.
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < n; ++i)
        if (!boxes[i].empty()) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return boxes[a].lo.x != boxes[b].lo.x ? boxes[a].lo.x < boxes[b].lo.x : a < b;
    });
    for (size_t i = 0; i < order.size(); ++i) {
        const Bounds3f& a = boxes[order[i]];
        for (size_t j = i + 1; j < order.size() && boxes[order[j]].lo.x <= a.hi.x + options.gap; ++j) {
            const Bounds3f& b = boxes[order[j]];
            if (b.lo.z <= a.hi.z + options.gap && a.lo.z <= b.hi.z + options.gap) forest.unite(order[i], order[j], options.maxExtent);
        }
    }
    PhotonBlockSet set;
    set.blockOfObject.assign(n, kNoBlock);
    std::vector<uint32_t> blockOfRoot(n, kNoBlock);
    Bounds3f all;
    for (uint32_t i : order) all.extend(boxes[i]);
    for (uint32_t i = 0; i < n; ++i) {
        if (boxes[i].empty()) continue;
        const uint32_t root = forest.find(i);
        if (blockOfRoot[root] == kNoBlock) {
            blockOfRoot[root] = uint32_t(set.blocks.size());
            const Bounds3f& b = forest.box[root];
            PhotonBlock block;
            block.lo = b.lo;
            block.hi = b.hi;
            block.centre = {0.5f * (b.lo.x + b.hi.x), 0.5f * (b.lo.z + b.hi.z)};
            block.groundLo = {b.lo.x, b.lo.z};
            block.groundHi = {b.hi.x, b.hi.z};
            set.blocks.push_back(block);
        }
        set.blockOfObject[i] = blockOfRoot[root];
    }
    if (set.blocks.empty()) return set;
    // The ground grid: each cell goes to the block whose rectangle is nearest its centre, within reach.
    const float reach = options.groundReach;
    const float width = all.hi.x - all.lo.x + 2 * reach, depth = all.hi.z - all.lo.z + 2 * reach;
    set.groundCell = std::max({options.groundCell, width / 2048.0f, depth / 2048.0f});
    set.groundLo = {all.lo.x - reach, all.lo.z - reach};
    set.groundW = uint32_t(std::ceil(width / set.groundCell));
    set.groundH = uint32_t(std::ceil(depth / set.groundCell));
    set.groundCells.assign(size_t(set.groundW) * set.groundH, kNoBlock);
    std::vector<float> nearest(set.groundCells.size(), reach);
    for (uint32_t k = 0; k < set.blocks.size(); ++k) {
        const Bounds3f box{set.blocks[k].lo, set.blocks[k].hi};
        const int x0 = std::max(0, int((box.lo.x - reach - set.groundLo.x) / set.groundCell));
        const int x1 = std::min(int(set.groundW) - 1, int((box.hi.x + reach - set.groundLo.x) / set.groundCell));
        const int z0 = std::max(0, int((box.lo.z - reach - set.groundLo.y) / set.groundCell));
        const int z1 = std::min(int(set.groundH) - 1, int((box.hi.z + reach - set.groundLo.y) / set.groundCell));
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) {
                const size_t cell = size_t(z) * set.groundW + x;
                const float d = distanceXz(box, set.groundLo.x + (x + 0.5f) * set.groundCell, set.groundLo.y + (z + 0.5f) * set.groundCell);
                if (d < nearest[cell] || (d == nearest[cell] && set.groundCells[cell] == kNoBlock)) {
                    nearest[cell] = d;
                    set.groundCells[cell] = k;
                }
            }
    }
    // Each block's orthographic layers cover its box and the ground cells it owns.
    for (uint32_t z = 0; z < set.groundH; ++z)
        for (uint32_t x = 0; x < set.groundW; ++x) {
            const uint32_t k = set.groundCells[size_t(z) * set.groundW + x];
            if (k == kNoBlock) continue;
            PhotonBlock& block = set.blocks[k];
            block.groundLo = {std::min(block.groundLo.x, set.groundLo.x + x * set.groundCell),
                              std::min(block.groundLo.y, set.groundLo.y + z * set.groundCell)};
            block.groundHi = {std::max(block.groundHi.x, set.groundLo.x + (x + 1) * set.groundCell),
                              std::max(block.groundHi.y, set.groundLo.y + (z + 1) * set.groundCell)};
        }
    return set;
}

} // namespace urbis
