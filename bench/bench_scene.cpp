#include "bench_scene.h"

#include <cmath>
#include <random>

namespace urbis::bench {
namespace {

/// The 12 triangles of the closed box [lo, hi].
void appendBox(std::vector<Triangle>& out, Vec3f lo, Vec3f hi) {
    const Vec3f c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                        {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
    for (const auto& q : quads) {
        out.push_back({c[q[0]], c[q[1]], c[q[2]]});
        out.push_back({c[q[0]], c[q[2]], c[q[3]]});
    }
}

} // namespace

std::vector<Triangle> benchTriangles() {
    constexpr int kLots = 256;          // lots per side
    constexpr float kLot = 25.0f;       // lot pitch, metres (street included)
    constexpr float kHalf = 0.5f * kLots * kLot;
    std::mt19937 rng(20240607u);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::lognormal_distribution<float> height(std::log(15.0f), 0.7f);
    std::vector<Triangle> tris;
    tris.reserve(size_t(kLots) * kLots * 18 + 2);
    for (int i = 0; i < kLots; ++i)
        for (int j = 0; j < kLots; ++j) {
            const float x0 = -kHalf + i * kLot + 2.0f + 3.0f * unit(rng);
            const float z0 = -kHalf + j * kLot + 2.0f + 3.0f * unit(rng);
            const float x1 = x0 + 8.0f + 10.0f * unit(rng), z1 = z0 + 8.0f + 10.0f * unit(rng);
            const float h = std::fmin(3.0f + height(rng), 250.0f);
            appendBox(tris, {x0, 0.0f, z0}, {x1, h, z1});
            if (unit(rng) < 0.5f) {   // a set-back upper part on half the buildings
                const float inset = 1.0f + 2.0f * unit(rng);
                appendBox(tris, {x0 + inset, h, z0 + inset}, {x1 - inset, h * (1.2f + 0.5f * unit(rng)), z1 - inset});
            }
        }
    const Vec3f g[4] = {{-kHalf, 0.0f, -kHalf}, {kHalf, 0.0f, -kHalf}, {kHalf, 0.0f, kHalf}, {-kHalf, 0.0f, kHalf}};
    tris.push_back({g[0], g[1], g[2]});
    tris.push_back({g[0], g[2], g[3]});
    return tris;
}

} // namespace urbis::bench
