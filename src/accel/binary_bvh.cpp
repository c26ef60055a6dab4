#include "accel/binary_bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cassert>

namespace urbis {
namespace {

constexpr uint32_t kMaxBins = 32;
/// Below this depth splits are by SAH; from it on by object median, which halves the count
/// at every level, so depth stays under 32 + log2(primitives) < 64.
constexpr uint32_t kMedianSplitDepth = 32;
/// Nodes with at least this many primitives bin and bound their primitives in parallel.
constexpr uint32_t kParallelBinningThreshold = 1u << 16;

/// Min and max as compare-and-select: g++ does not inline fminf/fmaxf (NaN rules), which
/// made them most of the build time.
float minOf(float a, float b) { return a < b ? a : b; }
float maxOf(float a, float b) { return a > b ? a : b; }

void grow(Bounds3f& box, const Bounds3f& other) {
    box.lo = {minOf(box.lo.x, other.lo.x), minOf(box.lo.y, other.lo.y), minOf(box.lo.z, other.lo.z)};
    box.hi = {maxOf(box.hi.x, other.hi.x), maxOf(box.hi.y, other.hi.y), maxOf(box.hi.z, other.hi.z)};
}

void grow(Bounds3f& box, Vec3f p) {
    box.lo = {minOf(box.lo.x, p.x), minOf(box.lo.y, p.y), minOf(box.lo.z, p.z)};
    box.hi = {maxOf(box.hi.x, p.x), maxOf(box.hi.y, p.y), maxOf(box.hi.z, p.z)};
}

/// Half the surface area (enough for SAH ratios); any value for an empty box, which
/// only ever appears next to a count of zero.
float halfArea(const Bounds3f& box) {
    const Vec3f d = box.extent();
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

struct Bin {
    Bounds3f bounds;
    uint32_t count = 0;
    uint32_t cost = 0;   ///< the primitives' intersection costs, in units of intersectionCost
};

/// SAH bins on the three axes. Merging takes counts and min/max only, so a parallel
/// reduction gives the same bins in any order: the build stays deterministic.
struct BinSet {
    Bin bins[3][kMaxBins];

    void merge(const BinSet& other, uint32_t binCount) {
        for (int axis = 0; axis < 3; ++axis)
            for (uint32_t i = 0; i < binCount; ++i) {
                grow(bins[axis][i].bounds, other.bins[axis][i].bounds);
                bins[axis][i].count += other.bins[axis][i].count;
                bins[axis][i].cost += other.bins[axis][i].cost;
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
    uint32_t primCost = 0;   ///< the node's primitives' intersection costs (a leaf's cost), in units
    Bounds3f leftBounds, rightBounds;
};

class Builder {
public:
    Builder(const std::vector<Bounds3f>& primBounds, const std::vector<uint32_t>& primCosts,
            const BvhBuildOptions& options, std::vector<uint32_t>& primOrder)
        : bounds_(primBounds), costs_(primCosts), options_(options), order_(primOrder) {
        const uint32_t n = static_cast<uint32_t>(primBounds.size());
        centroids_.resize(n);
        order_.resize(n);
        for (uint32_t i = 0; i < n; ++i) {
            centroids_[i] = primBounds[i].centre();
            order_[i] = i;
        }
        // A subtree over primitives [b, e) owns the 2(e-b)-1 slots that start at its own:
        // tasks write disjoint slots and no counter is shared between threads.
        slots_.resize(2 * size_t(n) - 1);
    }

    /// Builds (at least one primitive) into slots, where an interior node's `first` is its right child's slot (the
    /// left child is the next slot).
    void run() {
        const uint32_t n = static_cast<uint32_t>(order_.size());
        build(0, 0, n, reduceBounds(0, n, false), 0);
    }

    /// The binary tree in its slots (an interior node's left child is the next slot), once built,
    /// moved out as it is: no compacted copy (64 bytes a primitive). The centroids are released first.
    std::vector<BinaryNode> takeSlots() {
        std::vector<Vec3f>().swap(centroids_);
        return std::move(slots_);
    }

private:
    static BinaryNode makeNode(const Bounds3f& box, uint32_t first, uint32_t primCount) {
        return {box, first, primCount};
    }

    /// Bounds of the primitives (or of their centroids) in order_[b, e).
    Bounds3f reduceBounds(uint32_t b, uint32_t e, bool centroids) const {
        auto body = [&](const tbb::blocked_range<uint32_t>& r, Bounds3f acc) {
            for (uint32_t i = r.begin(); i != r.end(); ++i) {
                if (centroids)
                    grow(acc, centroids_[order_[i]]);
                else
                    grow(acc, bounds_[order_[i]]);
            }
            return acc;
        };
        if (e - b < kParallelBinningThreshold) return body({b, e}, Bounds3f{});
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(b, e, 4096), Bounds3f{}, body,
            [](Bounds3f x, const Bounds3f& y) { grow(x, y); return x; });
    }

    void binRange(uint32_t b, uint32_t e, const BinMapping& map, BinSet& set) const {
        for (uint32_t i = b; i < e; ++i) {
            const uint32_t prim = order_[i];
            const Vec3f c = centroids_[prim];
            for (int axis = 0; axis < 3; ++axis) {
                Bin& bin = set.bins[axis][map.binOf(c[axis], axis)];
                grow(bin.bounds, bounds_[prim]);
                ++bin.count;
                bin.cost += costs_.empty() ? 1u : costs_[prim];
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

    /// The SAH's cost of a leaf of primitives costing `cost` units: whole groups of leafGroupSize.
    float leafCostOf(uint32_t cost) const {
        return float((cost + options_.leafGroupSize - 1) / options_.leafGroupSize);
    }

    /// The cheapest SAH split over all axes (Wald 2007, section 3), relative to the
    /// node's area.
    Split findSplit(uint32_t b, uint32_t e, const BinMapping& map, float nodeHalfArea) const {
        const BinSet set = fillBins(b, e, map);
        const uint32_t nb = map.binCount;
        Split best;
        for (uint32_t i = 0; i < nb; ++i) best.primCost += set.bins[0][i].cost;
        for (int axis = 0; axis < 3; ++axis) {
            if (map.scale[axis] == 0.0f) continue;
            const Bin* bins = set.bins[axis];
            // Sweep from the right: cost of the right side for every split position.
            float rightCost[kMaxBins];
            Bounds3f acc;
            uint32_t count = 0, cost = 0;
            for (uint32_t i = nb - 1; i > 0; --i) {
                grow(acc, bins[i].bounds);
                count += bins[i].count;
                cost += bins[i].cost;
                rightCost[i] = count > 0 ? halfArea(acc) * leafCostOf(cost) : -1.0f;
            }
            acc = Bounds3f{};
            count = cost = 0;
            for (uint32_t i = 1; i < nb; ++i) {
                grow(acc, bins[i - 1].bounds);
                count += bins[i - 1].count;
                cost += bins[i - 1].cost;
                if (count == 0 || rightCost[i] < 0.0f) continue;
                const float splitCost = options_.traversalCost +
                                        options_.intersectionCost * (halfArea(acc) * leafCostOf(cost) + rightCost[i]) / nodeHalfArea;
                if (best.axis < 0 || splitCost < best.cost) {
                    best.axis = axis;
                    best.bin = i;
                    best.cost = splitCost;
                }
            }
        }
        if (best.axis >= 0)
            for (uint32_t i = 0; i < nb; ++i)
                grow(i < best.bin ? best.leftBounds : best.rightBounds, set.bins[best.axis][i].bounds);
        return best;
    }

    void build(uint32_t slot, uint32_t b, uint32_t e, const Bounds3f& box, uint32_t depth) {
        const uint32_t count = e - b;
        if (count == 1) {
            slots_[slot] = makeNode(box, b, count);
            return;
        }
        BinMapping map;
        // Small nodes get fewer bins: about one per primitive is as good, and much cheaper.
        map.binCount = std::clamp(std::min(options_.binCount, 2 * count), 2u, kMaxBins);
        map.centroidBounds = reduceBounds(b, e, true);
        const Vec3f extent = map.centroidBounds.extent();
        for (int axis = 0; axis < 3; ++axis)
            map.scale[axis] = extent[axis] > 0.0f ? float(map.binCount) / extent[axis] : 0.0f;
        const bool splittable = extent.x > 0.0f || extent.y > 0.0f || extent.z > 0.0f;

        // A primitive that costs more than a triangle gets a leaf of its own: the traversal defers
        // such leaves and tests them with their own routine (wide_bvh_traverse.h).
        const bool leafAllowed = count <= options_.maxLeafSize && !holdsCostly(b, e);
        uint32_t mid;
        if (splittable && depth < kMedianSplitDepth) {
            const Split split = findSplit(b, e, map, halfArea(box));
            const float leafCost = options_.intersectionCost * leafCostOf(split.primCost);
            if (split.axis < 0 || (leafAllowed && leafCost <= split.cost)) {
                if (leafAllowed) {
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
            if (leafAllowed) {
                slots_[slot] = makeNode(box, b, count);
                return;
            }
            mid = medianSplit(b, e, map);
        }
        finishInterior(slot, b, mid, e, box, reduceBounds(b, mid, false), reduceBounds(mid, e, false), depth);
    }

    /// Whether order_[b, e) holds a primitive of cost above one.
    bool holdsCostly(uint32_t b, uint32_t e) const {
        if (costs_.empty()) return false;
        for (uint32_t i = b; i < e; ++i)
            if (costs_[order_[i]] > 1) return true;
        return false;
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
    const std::vector<uint32_t>& costs_;
    const BvhBuildOptions& options_;
    std::vector<uint32_t>& order_;
    std::vector<Vec3f> centroids_;
    std::vector<BinaryNode> slots_;
};

} // namespace

int gatherLanes(const std::vector<BinaryNode>& binary, uint32_t top, uint32_t* lanes, int maxLanes) {
    if (binary[top].isLeaf()) {
        lanes[0] = top;   // a root that is a leaf
        return 1;
    }
    int count = 0;
    lanes[count++] = top + 1;
    lanes[count++] = binary[top].first;
    while (count < maxLanes) {
        int open = -1;
        for (int l = 0; l < count; ++l) {
            const BinaryNode& n = binary[lanes[l]];
            if (!n.isLeaf() && (open < 0 || n.box.area() > binary[lanes[open]].box.area())) open = l;
        }
        if (open < 0) break;
        const uint32_t opened = lanes[open];
        for (int l = count; l > open + 1; --l) lanes[l] = lanes[l - 1];
        lanes[open] = opened + 1;
        lanes[open + 1] = binary[opened].first;
        ++count;
    }
    return count;
}

BinaryBvh buildBinaryBvh(const std::vector<Bounds3f>& primBounds, const BvhBuildOptions& options,
                         const std::vector<uint32_t>& primCosts) {
    BinaryBvh binary;
    Builder builder(primBounds, primCosts, options, binary.primOrder);
    builder.run();
    binary.nodes = builder.takeSlots();
    return binary;
}

} // namespace urbis
