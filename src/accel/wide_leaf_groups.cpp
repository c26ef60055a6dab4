#include "accel/wide_leaf_groups.h"

#include <algorithm>
#include <numeric>

namespace urbis {

std::vector<WideLeafGroup> groupWideLeaves(WideBvh& bvh, uint32_t width) {
    // Nodes in the order of their first primitive, so that the groups follow primOrder.
    std::vector<uint32_t> order(bvh.nodes.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return bvh.nodes[a].primBase < bvh.nodes[b].primBase; });
    std::vector<WideLeafGroup> groups;
    groups.reserve(bvh.primOrder.size() / width + bvh.nodes.size());
    for (uint32_t index : order) {
        WideBvhNode& node = bvh.nodes[index];
        uint32_t first = node.primBase;
        node.primBase = uint32_t(groups.size());
        for (int l = 0; l < kWideBvhWidth; ++l) {
            const uint32_t size = node.leafSize(l);
            if (size == 0) continue;
            const uint32_t count = (size + width - 1) / width;
            for (uint32_t g = 0; g < count; ++g) groups.push_back({first + g * width, std::min(width, size - g * width)});
            node.leafInfo[l] = uint8_t(count | (node.leafInfo[l] & kWideCostlyLeaf));
            first += size;
        }
    }
    return groups;
}

} // namespace urbis
