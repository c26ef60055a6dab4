// Checks on closed triangle meshes shared by the mesher tests: open edges and enclosed volume.
#pragma once

#include "scene/triangle_mesh.h"

#include <array>
#include <cmath>
#include <map>
#include <queue>
#include <tuple>
#include <vector>

namespace urbis::test {

/// Edges not shared by exactly two triangles (vertices compared exactly): 0 for a closed mesh.
inline size_t openEdges(const TriangleMesh& mesh) {
    using Key = std::tuple<float, float, float, float, float, float>;
    std::map<Key, int> edges;
    auto add = [&](Vec3f a, Vec3f b) {
        if (std::tie(a.x, a.y, a.z) > std::tie(b.x, b.y, b.z)) std::swap(a, b);
        ++edges[{a.x, a.y, a.z, b.x, b.y, b.z}];
    };
    for (const Triangle& t : mesh.triangles) {
        add(t.p0, t.p1);
        add(t.p1, t.p2);
        add(t.p2, t.p0);
    }
    size_t open = 0;
    for (const auto& [edge, n] : edges) open += n != 2;
    return open;
}

/// Volume enclosed by a closed mesh whose triangles may be wound either way: windings are made
/// consistent across shared edges (breadth first), then the divergence theorem sums the signed
/// tetrahedra to the origin, per connected part.
inline double closedVolume(const TriangleMesh& mesh) {
    std::map<std::tuple<float, float, float>, uint32_t> ids;
    std::vector<Vec3f> points;
    std::vector<std::array<uint32_t, 3>> tris;
    for (const Triangle& t : mesh.triangles) {
        std::array<uint32_t, 3> ids3{};
        const Vec3f p[3] = {t.p0, t.p1, t.p2};
        for (int k = 0; k < 3; ++k) {
            auto [it, inserted] = ids.try_emplace({p[k].x, p[k].y, p[k].z}, uint32_t(points.size()));
            if (inserted) points.push_back(p[k]);
            ids3[k] = it->second;
        }
        tris.push_back(ids3);
    }
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> byEdge;
    for (size_t i = 0; i < tris.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = tris[i][k], b = tris[i][(k + 1) % 3];
            byEdge[{std::min(a, b), std::max(a, b)}].push_back(i);
        }
    auto hasDirected = [&](const std::array<uint32_t, 3>& t, uint32_t a, uint32_t b) {
        for (int k = 0; k < 3; ++k)
            if (t[k] == a && t[(k + 1) % 3] == b) return true;
        return false;
    };
    std::vector<int> flipped(tris.size(), -1);
    double total = 0;
    for (size_t seed = 0; seed < tris.size(); ++seed) {
        if (flipped[seed] >= 0) continue;
        double part = 0;
        std::queue<size_t> todo;
        flipped[seed] = 0;
        todo.push(seed);
        while (!todo.empty()) {
            size_t i = todo.front();
            todo.pop();
            std::array<uint32_t, 3> t = tris[i];
            if (flipped[i]) std::swap(t[1], t[2]);
            const Vec3f a = points[t[0]], b = points[t[1]], c = points[t[2]];
            part += (double(a.x) * (double(b.y) * c.z - double(b.z) * c.y) - double(a.y) * (double(b.x) * c.z - double(b.z) * c.x) +
                     double(a.z) * (double(b.x) * c.y - double(b.y) * c.x)) / 6.0;
            for (int k = 0; k < 3; ++k) {
                const uint32_t u = t[k], v = t[(k + 1) % 3];
                for (size_t j : byEdge[{std::min(u, v), std::max(u, v)}]) {
                    if (flipped[j] >= 0) continue;
                    flipped[j] = hasDirected(tris[j], u, v) ? 1 : 0;  // a neighbour walks the edge v -> u
                    todo.push(j);
                }
            }
        }
        total += std::abs(part);
    }
    return total;
}

} // namespace urbis::test
