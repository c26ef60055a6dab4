#include "lights/light_bvh_build.h"

#include "math/constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace urbis {

namespace {

/// Angle between two unit vectors, radians (double: the build is not per ray).
double angleBetween(Vec3f a, Vec3f b) { return std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)); }

/// The unit vector `v` turned by `angle` radians about the unit axis `k`, perpendicular to it
/// (Rodrigues' formula without its k (k . v) term, which is zero).
Vec3f turnAbout(Vec3f v, Vec3f k, double angle) {
    const Vec3f kv = cross(k, v);
    const double c = std::cos(angle), s = std::sin(angle);
    return normalize(Vec3f{float(v.x * c + kv.x * s), float(v.y * c + kv.y * s), float(v.z * c + kv.z * s)});
}

/// Where the BVH leaves its centroid-bucket splits for the count median: past this depth every trail
/// still fits in 64 bits for up to 2^23 lights.
constexpr int kMedianSplitDepth = 40;
constexpr int kBuckets = 12;  ///< centroid buckets per axis (pbrt-v4)

/// The cost of a node of bounds `b` split along `axis` of `parent` (pbrt-v4
/// BVHLightSampler::EvaluateCost; Conty Estevez and Kulla 2018, equation 2): power times the
/// orientation cone's measure M_Omega times the box's area, with the regularisation Kr that
/// penalises thin slices of a long box.
double splitCost(const LightBounds& b, const Bounds3f& parent, int axis) {
    if (b.phi == 0) return 0;
    const double thetaO = std::acos(std::clamp(double(b.cosThetaO), -1.0, 1.0));
    const double thetaE = std::acos(std::clamp(double(b.cosThetaE), -1.0, 1.0));
    const double thetaW = std::min(thetaO + thetaE, double(kPi));
    const double sinO = std::sqrt(std::max(0.0, 1.0 - double(b.cosThetaO) * b.cosThetaO));
    const double mOmega = 2 * kPi * (1 - b.cosThetaO) +
                          kPi / 2 * (2 * thetaW * sinO - std::cos(thetaO - 2 * thetaW) - 2 * thetaO * sinO + b.cosThetaO);
    const Vec3f d = parent.extent();
    const double kr = d[axis] > 0 ? double(maxComponent(d)) / d[axis] : 1.0;
    return double(b.phi) * mOmega * kr * double(b.bounds.area());
}

struct Builder {
    const std::vector<LightBounds>& bounds;
    LightBvh& out;

    static Vec3f centroid(const LightBounds& b) { return b.bounds.centre(); }

    /// The bucket of `c` along `axis` of the centroids' box `box`.
    static int bucketOf(const Bounds3f& box, Vec3f c, int axis) {
        const float extent = box.hi[axis] - box.lo[axis];
        const int b = int(float(kBuckets) * ((c[axis] - box.lo[axis]) / extent));
        return std::clamp(b, 0, kBuckets - 1);
    }

    /// Builds the subtree over lights[start, end) at `depth` with trail `trail`; returns the node's
    /// index and its bounds. Recursion depth is the tree's (at most 64).
    std::pair<uint32_t, LightBounds> build(std::vector<uint32_t>& lights, size_t start, size_t end, uint64_t trail, int depth) {
        if (depth >= 64) throw std::length_error("light BVH deeper than its 64-bit trails");
        const uint32_t nodeIndex = uint32_t(out.nodes.size());
        out.nodes.emplace_back();
        if (end - start == 1) {
            const LightBounds& b = bounds[lights[start]];
            out.trails[lights[start]] = trail;
            setNode(nodeIndex, b, LightBvhNode::kLeafBit | lights[start]);
            return {nodeIndex, b};
        }
        Bounds3f box, centroids;
        for (size_t i = start; i < end; ++i) {
            box.extend(bounds[lights[i]].bounds);
            centroids.extend(centroid(bounds[lights[i]]));
        }
        const size_t mid = split(lights, start, end, box, centroids, depth);
        // The first child is the next node, by the layout; the second's index goes into this node.
        const LightBounds b0 = build(lights, start, mid, trail, depth + 1).second;
        const auto [second, b1] = build(lights, mid, end, trail | (uint64_t(1) << depth), depth + 1);
        const LightBounds b = unionLightBounds(b0, b1);
        setNode(nodeIndex, b, second);
        return {nodeIndex, b};
    }

    void setNode(uint32_t index, const LightBounds& b, uint32_t packed) {
        if ((packed & LightBvhNode::kIndexMask) != (packed & ~LightBvhNode::kLeafBit))
            throw std::length_error("too many lights for the light BVH's 30-bit indices");
        LightBvhNode& node = out.nodes[index];
        node.bounds = b.bounds;
        node.axis = b.axis;
        node.cosThetaO = b.cosThetaO;
        node.cosThetaE = b.cosThetaE;
        node.phi = b.phi;
        node.packed = packed | (b.twoSided ? LightBvhNode::kTwoSidedBit : 0u);
    }

    /// Where lights[start, end) split: the least cost over the bucket boundaries of the three axes
    /// (ties to the lower axis and bucket), or the count median along the centroids' longest axis where
    /// no boundary splits them or the tree is deep. Reorders lights[start, end) accordingly.
    size_t split(std::vector<uint32_t>& lights, size_t start, size_t end, const Bounds3f& box, const Bounds3f& centroids,
                 int depth) {
        double best = INFINITY;
        int bestAxis = -1, bestBucket = -1;
        for (int axis = 0; axis < 3 && depth < kMedianSplitDepth; ++axis) {
            if (!(centroids.hi[axis] > centroids.lo[axis])) continue;
            std::array<LightBounds, kBuckets> buckets{};
            std::array<size_t, kBuckets> counts{};
            for (size_t i = start; i < end; ++i) {
                const LightBounds& b = bounds[lights[i]];
                const int k = bucketOf(centroids, centroid(b), axis);
                buckets[k] = unionLightBounds(buckets[k], b);
                ++counts[k];
            }
            // Prefix unions from below and from above, so each boundary's cost is two lookups.
            std::array<LightBounds, kBuckets> below{}, above{};
            std::array<size_t, kBuckets> countBelow{};
            for (int k = 0; k < kBuckets; ++k) {
                below[k] = k == 0 ? buckets[0] : unionLightBounds(below[k - 1], buckets[k]);
                countBelow[k] = (k == 0 ? 0 : countBelow[k - 1]) + counts[k];
            }
            for (int k = kBuckets - 1; k >= 0; --k)
                above[k] = k == kBuckets - 1 ? buckets[k] : unionLightBounds(above[k + 1], buckets[k]);
            for (int k = 0; k + 1 < kBuckets; ++k) {
                if (countBelow[k] == 0 || countBelow[k] == end - start) continue;
                const double cost = splitCost(below[k], box, axis) + splitCost(above[k + 1], box, axis);
                if (cost < best) {
                    best = cost;
                    bestAxis = axis;
                    bestBucket = k;
                }
            }
        }
        auto first = lights.begin() + std::ptrdiff_t(start), last = lights.begin() + std::ptrdiff_t(end);
        if (bestAxis >= 0) {
            const auto middle = std::stable_partition(first, last, [&](uint32_t l) {
                return bucketOf(centroids, centroid(bounds[l]), bestAxis) <= bestBucket;
            });
            return size_t(middle - lights.begin());
        }
        const int axis = maxAbsAxis(centroids.extent());
        const auto middle = first + std::ptrdiff_t((end - start) / 2);
        std::nth_element(first, middle, last, [&](uint32_t a, uint32_t b) {
            const float ca = centroid(bounds[a])[axis], cb = centroid(bounds[b])[axis];
            return ca < cb || (ca == cb && a < b);
        });
        return size_t(middle - lights.begin());
    }
};

} // namespace

LightBounds unionLightBounds(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0) return b;
    if (b.phi == 0) return a;
    LightBounds u = a;
    u.bounds.extend(b.bounds);
    u.phi = a.phi + b.phi;
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    // The cone of normals holding both (pbrt-v4 Union(DirectionCone, DirectionCone)). Every
    // direction, or one same cone, needs no trigonometry (most unions high in the tree, and the
    // windows of one wall).
    if (a.cosThetaO <= -1.0f || (b.cosThetaO == a.cosThetaO && b.axis.x == a.axis.x && b.axis.y == a.axis.y && b.axis.z == a.axis.z))
        return u;
    if (b.cosThetaO <= -1.0f) {
        u.cosThetaO = -1.0f;
        return u;
    }
    const double thetaA = std::acos(std::clamp(double(a.cosThetaO), -1.0, 1.0));
    const double thetaB = std::acos(std::clamp(double(b.cosThetaO), -1.0, 1.0));
    const double thetaD = angleBetween(a.axis, b.axis);
    if (std::min(thetaD + thetaB, double(kPi)) <= thetaA) return u;
    if (std::min(thetaD + thetaA, double(kPi)) <= thetaB) {
        u.axis = b.axis;
        u.cosThetaO = b.cosThetaO;
        return u;
    }
    const double thetaO = 0.5 * (thetaA + thetaD + thetaB);
    const Vec3f k = cross(a.axis, b.axis);
    if (thetaO >= kPi || !(dot(k, k) > 0.0f)) {
        u.cosThetaO = -1;  // every direction
        return u;
    }
    u.axis = turnAbout(a.axis, normalize(k), thetaO - thetaA);
    u.cosThetaO = float(std::cos(thetaO));
    return u;
}

LightBvh buildLightBvh(const std::vector<LightBounds>& lights) {
    LightBvh out;
    out.trails.assign(lights.size(), kNoLightTrail);
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (lights[i].phi > 0) order.push_back(i);
    if (order.empty()) return out;
    out.nodes.reserve(2 * order.size() - 1);
    Builder{lights, out}.build(order, 0, order.size(), 0, 0);
    return out;
}

} // namespace urbis
