#include "citygen/street_grades.h"

#include "citygen/plane_geometry.h"
#include "citygen/terrain_samples.h"
#include "scene/surface_part.h"

#include <algorithm>
#include <cstdint>

namespace urbis {
namespace {

/// Box average of `n` values `stride` apart from `first`, over 2k + 1 of them, edges repeated.
void boxPass(float* first, size_t stride, int n, int k, std::vector<float>& scratch) {
    scratch.clear();
    for (int i = 0; i < n; ++i) scratch.push_back(first[size_t(i) * stride]);
    double sum = 0;
    auto at = [&](int i) { return double(scratch[size_t(std::clamp(i, 0, n - 1))]); };
    for (int i = -k; i <= k; ++i) sum += at(i);
    for (int i = 0; i < n; ++i) {
        first[size_t(i) * stride] = float(sum / double(2 * k + 1));
        sum += at(i + k + 1) - at(i - k);
    }
}

bool gradedPart(uint32_t part) {
    const auto p = SurfacePart(part);
    return p == SurfacePart::Road || p == SurfacePart::Junction || p == SurfacePart::Sidewalk || p == SurfacePart::Curb;
}

} // namespace

std::vector<float> smoothedHeights(const TerrainField& terrain, float radius) {
    const TerrainRecord& r = terrain.record;
    std::vector<float> h = terrainHeights(terrain);
    // Two boxes of 2k + 1 samples make a tent of half-width about (2k + 1) cells.
    const int k = std::max(1, int(std::lround((radius / r.cell - 1.0f) * 0.5f)));
    std::vector<float> scratch;
    for (int pass = 0; pass < 2; ++pass) {
        for (uint32_t j = 0; j < r.nz; ++j) boxPass(h.data() + size_t(j) * r.nx, 1, int(r.nx), k, scratch);
        for (uint32_t i = 0; i < r.nx; ++i) boxPass(h.data() + i, r.nx, int(r.nz), k, scratch);
    }
    return h;
}

void gradeStreets(TerrainField& terrain, const CityMesh& mesh, const std::vector<float>& graded) {
    const TerrainRecord& r = terrain.record;
    std::vector<float> heights = terrainHeights(terrain);
    const TriangleMesh& tris = mesh.mesh;
    for (size_t n = 0; n < tris.size(); ++n) {
        const Triangle& t = tris.triangles[n];
        if (!gradedPart(tris.info[n].part) || std::max({t.p0.y, t.p1.y, t.p2.y}) >= kAtGround) continue;
        const Bounds3f box = primBounds(t);
        int i0, i1, j0, j1;
        if (!gridSamplesIn(box.lo.x - r.cell, box.hi.x + r.cell, r.x0, r.cell, r.nx, i0, i1) ||
            !gridSamplesIn(box.lo.z - r.cell, box.hi.z + r.cell, r.z0, r.cell, r.nz, j0, j1))
            continue;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const float x = r.x0 + r.cell * float(i), z = r.z0 + r.cell * float(j);
                const bool near = insidePlaneTriangle(t, x, z) || planeSegmentDistance(x, z, t.p0, t.p1) <= r.cell ||
                                  planeSegmentDistance(x, z, t.p1, t.p2) <= r.cell ||
                                  planeSegmentDistance(x, z, t.p2, t.p0) <= r.cell;
                const size_t s = size_t(j) * r.nx + size_t(i);
                if (near) heights[s] = graded[s];
            }
    }
    setTerrainHeights(terrain, std::move(heights));
}

} // namespace urbis
