// City-like triangle scenes for the accel and geometry tests: closed boxes with shared
// edges, a ground grid and long thin triangles, all from a seed.
#pragma once

#include "accel/wide_bvh_traverse.h"
#include "geometry/triangle_intersect.h"
#include "math/bounds.h"
#include "scene/triangle.h"

#include <cfloat>
#include <cstdint>
#include <random>
#include <vector>

namespace urbis::test {

/// The instruction sets of the wide traversal (lane test and block test) this CPU runs.
inline std::vector<WideIsa> wideIsasHere() {
    std::vector<WideIsa> isas{WideIsa::Scalar};
#if URBIS_HAVE_SSE
    isas.push_back(WideIsa::Sse);
    if (hostWideIsa() == WideIsa::Avx2) isas.push_back(WideIsa::Avx2);
#endif
    return isas;
}

/// The 12 triangles of the closed box [lo, hi] (shared edges and vertices).
inline void appendBox(std::vector<Triangle>& out, Vec3f lo, Vec3f hi) {
    const Vec3f c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                        {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
    for (const auto& q : quads) {
        out.push_back({c[q[0]], c[q[1]], c[q[2]]});
        out.push_back({c[q[0]], c[q[2]], c[q[3]]});
    }
}

/// Thousands of random buildings (boxes) on the ground, a triangulated ground grid, and long
/// thin triangles (wires, kerbs) across the city. Metres, y up.
inline std::vector<Triangle> makeCityScene(uint32_t seed, int boxCount = 800, int thinCount = 500) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-100.0f, 100.0f), size(1.0f, 12.0f), height(2.0f, 60.0f);
    std::vector<Triangle> tris;
    for (int i = 0; i < boxCount; ++i) {
        const float x = pos(rng), z = pos(rng), sx = size(rng), sz = size(rng);
        appendBox(tris, {x, 0.0f, z}, {x + sx, height(rng), z + sz});
    }
    constexpr int kGrid = 32;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            auto p = [](int a, int b) { return Vec3f{-110.0f + 220.0f * a / kGrid, 0.0f, -110.0f + 220.0f * b / kGrid}; };
            tris.push_back({p(i, j), p(i + 1, j), p(i + 1, j + 1)});
            tris.push_back({p(i, j), p(i + 1, j + 1), p(i, j + 1)});
        }
    std::uniform_real_distribution<float> y(0.5f, 40.0f), w(0.01f, 0.2f);
    for (int i = 0; i < thinCount; ++i) {
        const Vec3f a{pos(rng), y(rng), pos(rng)}, b{pos(rng), y(rng), pos(rng)};
        tris.push_back({a, b, b + Vec3f{0.0f, w(rng), 0.0f}});
    }
    return tris;
}

inline std::vector<Bounds3f> triangleBounds(const std::vector<Triangle>& tris) {
    std::vector<Bounds3f> bounds(tris.size());
    for (size_t i = 0; i < tris.size(); ++i) {
        bounds[i].extend(tris[i].p0);
        bounds[i].extend(tris[i].p1);
        bounds[i].extend(tris[i].p2);
    }
    return bounds;
}

/// The triangles in the leaf order of a Bvh or a WideBvh.
template <typename Tree>
std::vector<Triangle> reorder(const std::vector<Triangle>& tris, const Tree& bvh) {
    std::vector<Triangle> sorted(tris.size());
    for (size_t i = 0; i < tris.size(); ++i) sorted[i] = tris[bvh.primOrder[i]];
    return sorted;
}

/// Whether box `in` lies inside box `out`.
inline bool inside(const Bounds3f& in, const Bounds3f& out) {
    return in.lo.x >= out.lo.x && in.lo.y >= out.lo.y && in.lo.z >= out.lo.z && in.hi.x <= out.hi.x &&
           in.hi.y <= out.hi.y && in.hi.z <= out.hi.z;
}

/// The box of all finite points: what a root's box must lie inside.
inline Bounds3f everywhere() { return {{-FLT_MAX, -FLT_MAX, -FLT_MAX}, {FLT_MAX, FLT_MAX, FLT_MAX}}; }

/// A depth-first walk over a BVH's nodes from the root (node 0), each with its depth (the root's is 1)
/// and the box its parent gave it: what the shape tests of both BVHs step through.
struct TreeWalk {
    struct Item {
        uint32_t node, depth;
        Bounds3f box;
    };
    std::vector<Item> stack{{0, 1, everywhere()}};
    uint32_t maxDepth = 0;

    /// Takes the next node into `it`; false when the walk is over.
    bool next(Item& it) {
        if (stack.empty()) return false;
        it = stack.back();
        stack.pop_back();
        maxDepth = maxDepth > it.depth ? maxDepth : it.depth;
        return true;
    }
    /// Queues node `child` of `parent`, whose box it must lie in.
    void push(uint32_t child, const Item& parent, const Bounds3f& box) { stack.push_back({child, parent.depth + 1, box}); }
};

/// Where makeCityScene's rays start (and end): around its buildings and up to twice their height.
inline const Bounds3f kCitySceneRayBox{{-120.0f, 0.1f, -120.0f}, {120.0f, 80.0f, 120.0f}};

/// Random rays from anywhere in `box`: half towards anywhere in it moved `drop` metres down, half
/// aimed at random points of random triangles; some short, some with unit directions.
inline std::vector<Ray> cityRays(const std::vector<Triangle>& tris, const Bounds3f& box, float drop, int count,
                                 uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<size_t> pick(0, tris.size() - 1);
    const Vec3f e = box.extent();
    auto anywhere = [&] { return Vec3f{box.lo.x + e.x * unit(rng), box.lo.y + e.y * unit(rng), box.lo.z + e.z * unit(rng)}; };
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3f o = anywhere();
        Vec3f target = anywhere();
        target.y -= drop;
        if (i % 2) {
            const Triangle& t = tris[pick(rng)];
            float a = unit(rng), b = unit(rng);
            if (a + b > 1.0f) {
                a = 1.0f - a;
                b = 1.0f - b;
            }
            target = t.p0 + (t.p1 - t.p0) * a + (t.p2 - t.p0) * b;
        }
        Ray ray{o, target - o};
        if (i % 7 == 0) ray.tmax = 0.5f + unit(rng);   // some short rays
        if (i % 11 == 0) ray.dir = normalize(ray.dir);
        rays.push_back(ray);
    }
    return rays;
}

/// The closest hit among all triangles, tested one by one (the reference for the BVHs).
inline Hit bruteForce(const std::vector<Triangle>& tris, Ray ray) {
    const WatertightRay wr(ray);
    Hit hit;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        float t, u, v;
        if (intersectTriangle(tris[i], ray, wr, t, u, v)) {
            hit = {i, t, u, v};
            ray.tmax = t;
        }
    }
    return hit;
}

} // namespace urbis::test
