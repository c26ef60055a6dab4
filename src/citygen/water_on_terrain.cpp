#include "citygen/water_on_terrain.h"

#include "citygen/plane_geometry.h"
#include "citygen/terrain_samples.h"
#include "scene/surface_part.h"
#include "streets/street_levels.h"
#include "streets/water_depth.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <tuple>

namespace urbis {
namespace {

/// A shore edge of a water body: its ends' world x and z (y 0).
struct ShoreEdge {
    Vec3f a, b;
};

/// The edges of `surface` that no other of its triangles shares: its outline and holes' (the
/// triangulation shares its inner edges' vertices bit for bit).
std::vector<ShoreEdge> shoreOf(const std::vector<Triangle>& surface) {
    using Key = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>;
    std::map<Key, int> uses;
    auto key = [](Vec3f p, Vec3f q) {
        Key a{std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.z), std::bit_cast<uint32_t>(q.x),
              std::bit_cast<uint32_t>(q.z)};
        Key b{std::get<2>(a), std::get<3>(a), std::get<0>(a), std::get<1>(a)};
        return std::min(a, b);
    };
    for (const Triangle& t : surface)
        for (const auto& [p, q] : {std::pair{t.p0, t.p1}, std::pair{t.p1, t.p2}, std::pair{t.p2, t.p0}}) ++uses[key(p, q)];
    std::vector<ShoreEdge> shore;
    for (const auto& [k, n] : uses)
        if (n == 1)
            shore.push_back({{std::bit_cast<float>(std::get<0>(k)), 0, std::bit_cast<float>(std::get<1>(k))},
                             {std::bit_cast<float>(std::get<2>(k)), 0, std::bit_cast<float>(std::get<3>(k))}});
    return shore;
}

/// A river's surface along `flow` (world x, z): points every `step` metres, each the ground there or
/// the point before it, whichever is lower, and kWaterLevel at least.
WaterLevel riverLevel(const std::vector<Vec2d>& flow, const TerrainField& terrain, float step) {
    WaterLevel river;
    float lowest = INFINITY;
    auto add = [&](Vec2d p) {
        lowest = std::min(lowest, std::max(kWaterLevel, terrain.heightAt(float(p.x), float(p.y))));
        river.line.push_back(p);
        river.heights.push_back(lowest);
    };
    add(flow.front());
    for (size_t i = 1; i < flow.size(); ++i) {
        const Vec2d a = flow[i - 1], b = flow[i];
        const int steps = std::max(1, int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
        for (int k = 1; k <= steps; ++k) {
            const double f = double(k) / double(steps);
            add({a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f});
        }
    }
    river.level = lowest;
    return river;
}

/// Calls f(sample index, x, z) for every sample of `r`'s grid under one of `surface`'s triangles (a
/// sample under two shared edges' triangles more than once).
template <typename F>
void forEachSampleUnder(const std::vector<Triangle>& surface, const TerrainRecord& r, F&& f) {
    for (const Triangle& t : surface) {
        const Bounds3f tb = primBounds(t);
        int i0, i1, j0, j1;
        if (!gridSamplesIn(tb.lo.x, tb.hi.x, r.x0, r.cell, r.nx, i0, i1) || !gridSamplesIn(tb.lo.z, tb.hi.z, r.z0, r.cell, r.nz, j0, j1))
            continue;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const float x = r.x0 + r.cell * float(i), z = r.z0 + r.cell * float(j);
                if (insidePlaneTriangle(t, x, z)) f(size_t(j) * r.nx + size_t(i), i, j, x, z);
            }
    }
}

/// Lowers `heights` (the grid of `r`) to at most cap + slope x distance, where cap is the river's
/// surface at the samples under it (INFINITY elsewhere): banks rising from the water at `slope`, a
/// valley where the river's level lies below the hills around it. A chamfer distance in two passes
/// (steps of one sample and of a diagonal, within 8 % of the Euclidean distance).
void carveBanks(std::vector<float>& heights, const TerrainRecord& r, std::vector<float> cap, float slope) {
    const int nx = int(r.nx), nz = int(r.nz);
    const float side = slope * r.cell, diagonal = side * std::numbers::sqrt2_v<float>;
    auto relax = [&](int i, int j, int di, int dj, float rise) {
        if (i + di < 0 || i + di >= nx || j + dj < 0 || j + dj >= nz) return;
        float& c = cap[size_t(j) * size_t(nx) + size_t(i)];
        c = std::min(c, cap[size_t(j + dj) * size_t(nx) + size_t(i + di)] + rise);
    };
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i) {
            relax(i, j, -1, 0, side);
            relax(i, j, -1, -1, diagonal);
            relax(i, j, 0, -1, side);
            relax(i, j, 1, -1, diagonal);
        }
    for (int j = nz - 1; j >= 0; --j)
        for (int i = nx - 1; i >= 0; --i) {
            relax(i, j, 1, 0, side);
            relax(i, j, 1, 1, diagonal);
            relax(i, j, 0, 1, side);
            relax(i, j, -1, 1, diagonal);
        }
    for (size_t s = 0; s < heights.size(); ++s) heights[s] = std::min(heights[s], cap[s]);
}

} // namespace

float WaterLevel::at(float x, float z) const {
    if (line.size() < 2) return level;
    double nearest = INFINITY;
    float height = level;
    for (size_t i = 1; i < line.size(); ++i) {
        const Vec2d a = line[i - 1], d{line[i].x - a.x, line[i].y - a.y};
        const double len2 = d.x * d.x + d.y * d.y;
        const double u = len2 > 0 ? std::clamp(((x - a.x) * d.x + (z - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
        const double dist = std::hypot(x - (a.x + u * d.x), z - (a.y + u * d.y));
        if (dist >= nearest) continue;
        nearest = dist;
        height = heights[i - 1] + float(u) * (heights[i] - heights[i - 1]);
    }
    return height;
}

std::map<uint32_t, std::vector<Triangle>> waterSurfacesOf(const CityMesh& mesh) {
    std::map<uint32_t, std::vector<Triangle>> surfaces;
    const TriangleMesh& tris = mesh.mesh;
    for (size_t i = 0; i < tris.size(); ++i)
        if (tris.info[i].part == uint32_t(SurfacePart::Water) && mesh.materials[tris.info[i].material].kind == MaterialKind::Water)
            surfaces[tris.info[i].object].push_back(tris.triangles[i]);
    return surfaces;
}

WaterLevels waterLevelsOn(const CityMesh& mesh, const TerrainField& terrain) {
    WaterLevels levels;
    const float step = 0.5f * terrain.record.cell;
    for (const auto& [object, surface] : waterSurfacesOf(mesh)) {
        if (const auto flow = mesh.waterFlows.find(object); flow != mesh.waterFlows.end() && flow->second.size() >= 2) {
            levels[object] = riverLevel(flow->second, terrain, step);
            continue;
        }
        if (const auto ele = mesh.waterElevations.find(object); ele != mesh.waterElevations.end()) {
            levels[object].level = ele->second;
            continue;
        }
        float lowest = INFINITY;
        for (const ShoreEdge& e : shoreOf(surface)) {
            const int steps = std::max(1, int(std::ceil(length(e.b - e.a) / step)));
            for (int k = 0; k <= steps; ++k) {
                const Vec3f p = e.a + (e.b - e.a) * (float(k) / float(steps));
                lowest = std::min(lowest, terrain.heightAt(p.x, p.z));
            }
        }
        levels[object].level = std::max(kWaterLevel, lowest);
    }
    return levels;
}

void carveRiverBanks(TerrainField& terrain, const CityMesh& mesh, const WaterLevels& levels, const WaterOptions& options) {
    const TerrainRecord& r = terrain.record;
    std::vector<float> heights = terrainHeights(terrain), surfaceOver(heights.size(), INFINITY);
    bool rivers = false;
    for (const auto& [object, surface] : waterSurfacesOf(mesh)) {
        const WaterLevel& level = levels.at(object);
        if (level.line.size() < 2) continue;
        rivers = true;
        forEachSampleUnder(surface, r, [&](size_t sample, int, int, float x, float z) {
            surfaceOver[sample] = std::min(surfaceOver[sample], level.at(x, z));
        });
    }
    if (!rivers) return;
    carveBanks(heights, r, std::move(surfaceOver), options.bankSlope);
    setTerrainHeights(terrain, std::move(heights));
}

void carveWaterBeds(TerrainField& terrain, const CityMesh& mesh, const WaterLevels& levels, const WaterOptions& options) {
    const TerrainRecord& r = terrain.record;
    std::vector<float> heights = terrainHeights(terrain);
    auto samplesIn = [&](float lo, float hi, float origin, uint32_t n, int& first, int& last) {
        return gridSamplesIn(lo, hi, origin, r.cell, n, first, last);
    };
    const float shelf = std::max(options.shelfWidth, 0.0f);
    for (const auto& [object, surface] : waterSurfacesOf(mesh)) {
        const WaterLevel& level = levels.at(object);
        // Distance to the shore of the samples within a shelf of it; farther ones lie at maxDepth.
        Bounds3f box;
        for (const Triangle& t : surface) box.extend(primBounds(t));
        int i0, i1, j0, j1;
        if (!samplesIn(box.lo.x, box.hi.x, r.x0, r.nx, i0, i1) || !samplesIn(box.lo.z, box.hi.z, r.z0, r.nz, j0, j1)) continue;
        const int w = i1 - i0 + 1;
        std::vector<float> distance(size_t(w) * size_t(j1 - j0 + 1), INFINITY);
        for (const ShoreEdge& e : shoreOf(surface)) {
            int a0, a1, b0, b1;
            if (!samplesIn(std::min(e.a.x, e.b.x) - shelf, std::max(e.a.x, e.b.x) + shelf, r.x0, r.nx, a0, a1) ||
                !samplesIn(std::min(e.a.z, e.b.z) - shelf, std::max(e.a.z, e.b.z) + shelf, r.z0, r.nz, b0, b1))
                continue;
            for (int j = std::max(b0, j0); j <= std::min(b1, j1); ++j)
                for (int i = std::max(a0, i0); i <= std::min(a1, i1); ++i) {
                    float& d = distance[size_t(j - j0) * w + size_t(i - i0)];
                    d = std::min(d, planeSegmentDistance(r.x0 + r.cell * float(i), r.z0 + r.cell * float(j), e.a, e.b));
                }
        }
        // Each sample under the surface goes down to the bank's profile below the level.
        forEachSampleUnder(surface, r, [&](size_t sample, int i, int j, float x, float z) {
            const float bed = level.at(x, z) - waterBedDepth(distance[size_t(j - j0) * w + size_t(i - i0)], options);
            heights[sample] = std::min(heights[sample], bed);
        });
    }
    setTerrainHeights(terrain, std::move(heights));
}

} // namespace urbis
