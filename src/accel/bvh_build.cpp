#include "accel/bvh_build.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cassert>

namespace urbis {
namespace {

constexpr uint32_t kMaxBins = 64;
/// Below this depth splits are by SAH; from it on by object median, which halves the count
/// at every level, so depth stays under 32 + log2(primitives) < 64.
constexpr uint32_t kMedianSplitDepth = 32;
/// Nodes with at least this many primitives bin and bound their primitives in parallel.
constexpr uint32_t kParallelBinningThreshold = 1u << 16;

struct Bin {
    Bounds3f bounds;
    uint32_t count = 0;
};

/// SAH bins on the three axes. Merging takes counts and min/max only, so a parallel
/// reduction gives the same bins in any order: the build stays deterministic.
struct BinSet {
    Bin bins[3][kMaxBins];

    void merge(const BinSet& other, uint32_t binCount) {
        for (int axis = 0; axis < 3; ++axis)
            for (uint32_t i = 0; i < binCount; ++i) {
                bins[axis][i].bounds.extend(other.bins[axis][i].bounds);
                bins[axis][i].count += other.bins[axis][i].count;
            }
    }
};

/// Where the centroids of a node lie, and how a centroid coordinate maps to a bin.
struct BinMapping {
    Bounds3f centroidBounds;
    float scale[3] = {0, 0, 0};
    uint32_t binCount = 0;

    uint32_t binOf(float c, int axis) const {
        const float f = (c - centroidBounds.lo[axis]) * scale[axis];
        const uint32_t i = f > 0.0f ? static_cast<uint32_t>(f) : 0u;
        return i < binCount ? i : binCount - 1;
    }
};

struct Split {
    int axis = -1;      ///< -1: no SAH split found
    uint32_t bin = 0;   ///< primitives in bins [0, bin) go left
    float cost = 0;
    Bounds3f leftBounds, rightBounds;
};

class Builder {
public:
    Builder(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options, Bvh& bvh)
        : bounds_(primBounds), options_(options), order_(bvh.primOrder) {
        const uint32_t n = static_cast<uint32_t>(primBounds.size());
        centroids_.resize(n);
        order_.resize(n);
        for (uint32_t i = 0; i < n; ++i) {
            centroids_[i] = primBounds[i].centre();
            order_[i] = i;
        }
        // A subtree over primitives [b, e) owns the 2(e-b)-1 slots that start at its own:
        // tasks write disjoint slots and no counter is shared between threads.
        slots_.resize(n > 0 ? 2 * size_t(n) - 1 : 1);
    }

    /// Builds into slots, where an interior node's `first` is its right child's slot (the
    /// left child is the next slot).
    void run() {
        const uint32_t n = static_cast<uint32_t>(order_.size());
        if (n == 0) {
            slots_[0] = makeNode(Bounds3f{}, 0, 0);
            return;
        }
        build(0, 0, n, reduceBounds(0, n, false), 0);
    }

    /// Lays the slots out depth first with siblings adjacent: the final node array.
    std::vector<BvhNode> compact() const {
        std::vector<BvhNode> nodes;
        nodes.reserve(slots_.size());
        nodes.push_back(slots_[0]);
        struct Pending {
            uint32_t node, slot;
        };
        std::vector<Pending> stack{{0, 0}};
        while (!stack.empty()) {
            const Pending p = stack.back();
            stack.pop_back();
            const BvhNode& s = slots_[p.slot];
            if (s.isLeaf() || order_.empty()) continue;
            const uint32_t leftSlot = p.slot + 1, rightSlot = s.first;
            const uint32_t k = static_cast<uint32_t>(nodes.size());
            nodes.push_back(slots_[leftSlot]);
            nodes.push_back(slots_[rightSlot]);
            nodes[p.node].first = k;
            stack.push_back({k + 1, rightSlot});
            stack.push_back({k, leftSlot});
        }
        return nodes;
    }

private:
    static BvhNode makeNode(const Bounds3f& box, uint32_t first, uint32_t primCount) {
        return {{box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z}, first, primCount};
    }

    /// Bounds of the primitives (or of their centroids) in order_[b, e).
    Bounds3f reduceBounds(uint32_t b, uint32_t e, bool centroids) const {
        auto body = [&](const tbb::blocked_range<uint32_t>& r, Bounds3f acc) {
            for (uint32_t i = r.begin(); i != r.end(); ++i) {
                if (centroids)
                    acc.extend(centroids_[order_[i]]);
                else
                    acc.extend(bounds_[order_[i]]);
            }
            return acc;
        };
        if (e - b < kParallelBinningThreshold) return body({b, e}, Bounds3f{});
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(b, e, 4096), Bounds3f{}, body,
            [](Bounds3f x, const Bounds3f& y) { x.extend(y); return x; });
    }

    void binRange(uint32_t b, uint32_t e, const BinMapping& map, BinSet& set) const {
        for (uint32_t i = b; i < e; ++i) {
            const uint32_t prim = order_[i];
            const Vec3f c = centroids_[prim];
            for (int axis = 0; axis < 3; ++axis) {
                Bin& bin = set.bins[axis][map.binOf(c[axis], axis)];
                bin.bounds.extend(bounds_[prim]);
                ++bin.count;
            }
        }
    }

    BinSet fillBins(uint32_t b, uint32_t e, const BinMapping& map) const {
        if (e - b < kParallelBinningThreshold) {
            BinSet set;
            binRange(b, e, map, set);
            return set;
        }
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(b, e, 8192), BinSet{},
            [&](const tbb::blocked_range<uint32_t>& r, BinSet set) {
                binRange(r.begin(), r.end(), map, set);
                return set;
            },
            [&](BinSet x, const BinSet& y) { x.merge(y, map.binCount); return x; });
    }

    /// The cheapest SAH split over all axes (Wald 2007, section 3), relative to the
    /// node's area.
    Split findSplit(uint32_t b, uint32_t e, const BinMapping& map, float nodeArea) const {
        const BinSet set = fillBins(b, e, map);
        const uint32_t nb = map.binCount;
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (map.scale[axis] == 0.0f) continue;
            const Bin* bins = set.bins[axis];
            // Sweep from the right: cost of the right side for every split position.
            float rightCost[kMaxBins];
            Bounds3f acc;
            uint32_t count = 0;
            for (uint32_t i = nb - 1; i > 0; --i) {
                acc.extend(bins[i].bounds);
                count += bins[i].count;
                rightCost[i] = count > 0 ? acc.area() * float(count) : -1.0f;
            }
            acc = Bounds3f{};
            count = 0;
            for (uint32_t i = 1; i < nb; ++i) {
                acc.extend(bins[i - 1].bounds);
                count += bins[i - 1].count;
                if (count == 0 || rightCost[i] < 0.0f) continue;
                const float cost = options_.traversalCost +
                                   options_.intersectionCost * (acc.area() * float(count) + rightCost[i]) / nodeArea;
                if (best.axis < 0 || cost < best.cost) {
                    best.axis = axis;
                    best.bin = i;
                    best.cost = cost;
                }
            }
        }
        if (best.axis >= 0)
            for (uint32_t i = 0; i < nb; ++i)
                (i < best.bin ? best.leftBounds : best.rightBounds).extend(set.bins[best.axis][i].bounds);
        return best;
    }

    void build(uint32_t slot, uint32_t b, uint32_t e, const Bounds3f& box, uint32_t depth) {
        const uint32_t count = e - b;
        if (count == 1) {
            slots_[slot] = makeNode(box, b, count);
            return;
        }
        BinMapping map;
        map.binCount = std::clamp(options_.binCount, 2u, kMaxBins);
        map.centroidBounds = reduceBounds(b, e, true);
        const Vec3f extent = map.centroidBounds.extent();
        for (int axis = 0; axis < 3; ++axis)
            map.scale[axis] = extent[axis] > 0.0f ? float(map.binCount) / extent[axis] : 0.0f;
        const bool splittable = extent.x > 0.0f || extent.y > 0.0f || extent.z > 0.0f;

        uint32_t mid;
        if (splittable && depth < kMedianSplitDepth) {
            const Split split = findSplit(b, e, map, box.area());
            const float leafCost = options_.intersectionCost * float(count);
            if (split.axis < 0 || (count <= options_.maxLeafSize && leafCost <= split.cost)) {
                if (count <= options_.maxLeafSize) {
                    slots_[slot] = makeNode(box, b, count);
                    return;
                }
                mid = medianSplit(b, e, map);
            } else {
                uint32_t* first = order_.data();
                mid = static_cast<uint32_t>(
                    std::partition(first + b, first + e,
                                   [&](uint32_t prim) {
                                       return map.binOf(centroids_[prim][split.axis], split.axis) < split.bin;
                                   }) -
                    first);
                assert(mid > b && mid < e);
                finishInterior(slot, b, mid, e, box, split.leftBounds, split.rightBounds, depth);
                return;
            }
        } else {
            if (count <= options_.maxLeafSize) {
                slots_[slot] = makeNode(box, b, count);
                return;
            }
            mid = medianSplit(b, e, map);
        }
        finishInterior(slot, b, mid, e, box, reduceBounds(b, mid, false), reduceBounds(mid, e, false), depth);
    }

    /// Splits order_[b, e) in two halves by centroid along the widest centroid axis.
    uint32_t medianSplit(uint32_t b, uint32_t e, const BinMapping& map) {
        const int axis = maxAbsAxis(map.centroidBounds.extent());
        const uint32_t mid = b + (e - b) / 2;
        uint32_t* first = order_.data();
        std::nth_element(first + b, first + mid, first + e, [&](uint32_t p, uint32_t q) {
            const float cp = centroids_[p][axis], cq = centroids_[q][axis];
            return cp < cq || (cp == cq && p < q);
        });
        return mid;
    }

    void finishInterior(uint32_t slot, uint32_t b, uint32_t mid, uint32_t e, const Bounds3f& box,
                        const Bounds3f& leftBox, const Bounds3f& rightBox, uint32_t depth) {
        const uint32_t leftSlot = slot + 1, rightSlot = slot + 2 * (mid - b);
        slots_[slot] = makeNode(box, rightSlot, 0);
        auto left = [&] { build(leftSlot, b, mid, leftBox, depth + 1); };
        auto right = [&] { build(rightSlot, mid, e, rightBox, depth + 1); };
        if (e - b >= options_.parallelThreshold) {
            tbb::parallel_invoke(left, right);
        } else {
            left();
            right();
        }
    }

    const std::vector<Bounds3f>& bounds_;
    const BvhBuildOptions& options_;
    std::vector<uint32_t>& order_;
    std::vector<Vec3f> centroids_;
    std::vector<BvhNode> slots_;
};

} // namespace

Bvh buildBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options) {
    Bvh bvh;
    Builder builder(primBounds, options, bvh);
    builder.run();
    bvh.nodes = builder.compact();
    return bvh;
}

float sahCost(const Bvh& bvh, const BvhBuildOptions& options) {
    const float rootArea = bvh.nodes[0].box().area();
    if (rootArea <= 0.0f) return 0.0f;
    double cost = 0.0;
    for (const BvhNode& node : bvh.nodes) {
        const double relArea = node.box().area() / rootArea;
        cost += relArea * (node.isLeaf() ? options.intersectionCost * node.primCount : options.traversalCost);
    }
    return static_cast<float>(cost);
}

} // namespace urbis
