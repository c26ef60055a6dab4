#include "export/welded_mesh.h"

#include <array>
#include <bit>
#include <unordered_map>

namespace urbis {

namespace {

using VertexBits = std::array<uint32_t, 3>;

struct VertexBitsHash {
    size_t operator()(const VertexBits& v) const {
        uint64_t h = 1469598103934665603ull;
        for (uint32_t x : v) h = (h ^ x) * 1099511628211ull;
        return size_t(h);
    }
};

} // namespace

WeldedMesh weldTriangles(const std::vector<Triangle>& triangles) {
    WeldedMesh mesh;
    std::unordered_map<VertexBits, uint32_t, VertexBitsHash> index;
    index.reserve(triangles.size() * 2);
    mesh.indices.reserve(triangles.size() * 3);
    for (const Triangle& t : triangles)
        for (const Vec3f& p : {t.p0, t.p1, t.p2}) {
            const VertexBits key{std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z)};
            auto [it, inserted] = index.try_emplace(key, uint32_t(mesh.positions.size()));
            if (inserted) {
                mesh.lo = mesh.positions.empty() ? p : vmin(mesh.lo, p);
                mesh.hi = mesh.positions.empty() ? p : vmax(mesh.hi, p);
                mesh.positions.push_back(p);
            }
            mesh.indices.push_back(it->second);
        }
    return mesh;
}

} // namespace urbis
