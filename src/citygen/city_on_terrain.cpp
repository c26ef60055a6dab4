#include "citygen/city_on_terrain.h"

#include "citygen/bridges_on_terrain.h"
#include "citygen/street_grades.h"
#include "scene/surface_part.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace urbis {
namespace {

/// The forests on the terrain, each cut into square tiles of whole cells with the ground's range under
/// each tile, so that a tile's box ends at its own hills' crowns: one box over the whole terrain's
/// range would send every ray above the valleys through kilometres of empty cells. Adjacent tiles share
/// their edges (the same floats), so every cell's tree belongs to one tile; their trees stand on the
/// terrain where the ray finds them (terrainHeight, whose range over a tile rangeIn bounds).
std::vector<ForestRecord> forestTilesOnTerrain(const std::vector<ForestRecord>& forests, const TerrainField& terrain) {
    constexpr float kTileMetres = 192.0f;
    constexpr double kMostTilesPerForest = 4096.0;
    std::vector<ForestRecord> tiles;
    for (const ForestRecord& forest : forests) {
        const float width = forest.x1 - forest.x0, depth = forest.z1 - forest.z0;
        // Whole cells a tile, more of them where a large forest would otherwise need too many tiles.
        const double minSide = std::sqrt(double(width) * double(depth) / kMostTilesPerForest);
        const float side = forest.cell * std::ceil(std::max<float>(kTileMetres, float(minSide)) / forest.cell);
        const int nx = std::max(1, int(std::ceil(width / side))), nz = std::max(1, int(std::ceil(depth / side)));
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i) {
                ForestRecord tile = forest;
                tile.onTerrain = 1;
                tile.x0 = i == 0 ? forest.x0 : forest.x0 + float(i) * side;
                tile.x1 = i == nx - 1 ? forest.x1 : forest.x0 + float(i + 1) * side;
                tile.z0 = k == 0 ? forest.z0 : forest.z0 + float(k) * side;
                tile.z1 = k == nz - 1 ? forest.z1 : forest.z0 + float(k + 1) * side;
                terrain.rangeIn(tile.x0, tile.z0, tile.x1, tile.z1, tile.groundLo, tile.groundHi);
                tiles.push_back(tile);
            }
    }
    return tiles;
}


/// Whether a triangle of this part belongs to a tree's twin (nature/tree_mesher.h).
bool isTreePart(uint32_t part) {
    return part == uint32_t(SurfacePart::TreeTrunk) || part == uint32_t(SurfacePart::TreeCrown);
}

/// Whether a triangle of this part belongs to the streets (roads to lamps) rather than a building.
bool isStreetPart(uint32_t part) { return part >= uint32_t(SurfacePart::Road) && !isTreePart(part); }

/// Vertices this close (metres) to a building's base are its base, and follow the lowest ground.
constexpr float kBaseTolerance = 0.01f;

/// How far (metres) the ground may bulge from a street triangle's plane before it is split.
constexpr float kStreetTolerance = 0.05f;

/// `t` lifted vertex by vertex by `lift(p)` (the ground under p, or a bridge's lift), split in four at
/// its edges' midpoints while an edge is longer than `edge` and the lift at a midpoint or the centre
/// lies over kStreetTolerance off the lifted triangle's plane; into `out`. Flat ground (beyond the
/// grid, on a plain) keeps it whole.
template <typename Lift>
void liftStreetTriangle(const Triangle& t, const Lift& lift, float edge, std::vector<Triangle>& out) {
    auto len2 = [](Vec3f a, Vec3f b) { return (a.x - b.x) * (a.x - b.x) + (a.z - b.z) * (a.z - b.z); };
    const float g0 = lift(t.p0), g1 = lift(t.p1), g2 = lift(t.p2);
    const Vec3f a = (t.p0 + t.p1) * 0.5f, b = (t.p1 + t.p2) * 0.5f, c = (t.p2 + t.p0) * 0.5f;
    const Vec3f m = (t.p0 + t.p1 + t.p2) * (1.0f / 3.0f);
    const float off = std::max({std::fabs(lift(a) - 0.5f * (g0 + g1)), std::fabs(lift(b) - 0.5f * (g1 + g2)),
                                std::fabs(lift(c) - 0.5f * (g2 + g0)), std::fabs(lift(m) - (g0 + g1 + g2) / 3.0f)});
    const float longest = std::max({len2(t.p0, t.p1), len2(t.p1, t.p2), len2(t.p2, t.p0)});
    if (longest <= edge * edge || off <= kStreetTolerance) {
        out.push_back({{t.p0.x, t.p0.y + g0, t.p0.z}, {t.p1.x, t.p1.y + g1, t.p1.z}, {t.p2.x, t.p2.y + g2, t.p2.z}});
        return;
    }
    liftStreetTriangle({t.p0, a, c}, lift, edge, out);
    liftStreetTriangle({a, t.p1, b}, lift, edge, out);
    liftStreetTriangle({c, b, t.p2}, lift, edge, out);
    liftStreetTriangle({a, b, c}, lift, edge, out);
}

/// How far each tree twin (by object) rises: the ground's height under its trunk's foot, the middle of
/// its lowest vertices (the trunk's bottom ring), so that it stands upright as its record would.
std::unordered_map<uint32_t, float> treeLifts(const TriangleMesh& tris, const TerrainField& terrain) {
    std::unordered_map<uint32_t, float> lowest;
    for (size_t i = 0; i < tris.size(); ++i) {
        if (!isTreePart(tris.info[i].part)) continue;
        auto [it, added] = lowest.try_emplace(tris.info[i].object, tris.triangles[i].p0.y);
        for (const Vec3f p : {tris.triangles[i].p0, tris.triangles[i].p1, tris.triangles[i].p2}) it->second = std::min(it->second, p.y);
    }
    struct Foot {
        double x = 0, z = 0;
        size_t n = 0;
    };
    std::unordered_map<uint32_t, Foot> feet;
    for (size_t i = 0; i < tris.size(); ++i) {
        if (!isTreePart(tris.info[i].part)) continue;
        const uint32_t object = tris.info[i].object;
        Foot& foot = feet[object];
        for (const Vec3f p : {tris.triangles[i].p0, tris.triangles[i].p1, tris.triangles[i].p2})
            if (p.y <= lowest.at(object) + kBaseTolerance) foot.x += p.x, foot.z += p.z, ++foot.n;
    }
    std::unordered_map<uint32_t, float> lifts;
    for (const auto& [object, foot] : feet) lifts[object] = terrain.heightAt(float(foot.x / foot.n), float(foot.z / foot.n));
    return lifts;
}

} // namespace

float streetEdgeOnTerrain(const TerrainField& terrain) { return 2.0f * terrain.record.cell; }

void placeCityOnTerrain(CityMesh& mesh, const TerrainField& terrain, const WaterLevels& water) {
    // Each building's box, from its triangles and its walls' bottom edges.
    std::unordered_map<uint32_t, Bounds3f> buildings;   // each building's box
    TriangleMesh& tris = mesh.mesh;
    for (size_t i = 0; i < tris.size(); ++i) {
        if (isStreetPart(tris.info[i].part) || isTreePart(tris.info[i].part)) continue;
        Bounds3f& box = buildings[tris.info[i].object];
        for (const Vec3f p : {tris.triangles[i].p0, tris.triangles[i].p1, tris.triangles[i].p2}) box.extend(p);
    }
    for (const WallRecord& w : mesh.walls) {
        Bounds3f& box = buildings[w.object];
        box.extend(w.origin);
        box.extend(w.origin + w.axisU * w.width);
    }
    // Entrance (the highest ground under the box) and base (the lowest) of each building.
    struct Levels {
        float bottom, entrance, base;
    };
    std::unordered_map<uint32_t, Levels> levels;
    for (const auto& [object, box] : buildings) {
        float lo, hi;
        terrain.rangeIn(box.lo.x, box.lo.z, box.hi.x, box.hi.z, lo, hi);
        levels[object] = {box.lo.y, hi, lo};
    }
    // A building's vertex rises by its entrance level; one at its base goes down to the lowest ground.
    auto lift = [&](Vec3f& p, const Levels& l) {
        p.y = p.y <= l.bottom + kBaseTolerance ? l.base + (p.y - l.bottom) : p.y + l.entrance;
    };
    TriangleMesh lifted;
    lifted.triangles.reserve(tris.size());
    lifted.info.reserve(tris.size());
    std::vector<Triangle> pieces;
    const float edge = streetEdgeOnTerrain(terrain);
    const std::unordered_map<uint32_t, float> trees = treeLifts(tris, terrain);
    const BridgesOnTerrain bridges(mesh.bridgeSpans, terrain);
    for (size_t i = 0; i < tris.size(); ++i) {
        const TriangleInfo info = tris.info[i];
        if (isTreePart(info.part)) {  // a tree twin rises as a whole, as its record does
            Triangle t = tris.triangles[i];
            const float dy = trees.at(info.object);
            t.p0.y += dy, t.p1.y += dy, t.p2.y += dy;
            lifted.add(t, info);
            continue;
        }
        if (!isStreetPart(info.part)) {
            Triangle t = tris.triangles[i];
            const Levels& l = levels.at(info.object);
            lift(t.p0, l), lift(t.p1, l), lift(t.p2, l);
            lifted.add(t, info);
            continue;
        }
        if (info.part == uint32_t(SurfacePart::Water)) {
            // A water body lies at its surface (flat, or falling along a river's line), over the
            // terrain that is its bed; a river's surface in pieces down to a quarter of a sample
            // spacing, so that it follows its fall (a running minimum, with kinks) within a few cm.
            if (const auto level = water.find(info.object); level != water.end()) {
                if (mesh.materials[info.material].kind != MaterialKind::Water) {
                    --mesh.trianglesByKind["water"];   // the flat ground's bed: the terrain replaces it
                    continue;
                }
                Triangle t = tris.triangles[i];
                t.p0.y = t.p1.y = t.p2.y = 0.0f;
                pieces.clear();
                liftStreetTriangle(t, [&](Vec3f p) { return level->second.at(p.x, p.z); }, 0.25f * terrain.record.cell, pieces);
                for (const Triangle& piece : pieces) lifted.add(piece, info);
                continue;
            }
        }
        // Street surfaces follow the ground vertex by vertex, in pieces short enough to stay on it; a
        // bridge's (a triangle above kAtGround over a deck) its deck's lift, a pier's foot the ground.
        const Triangle& flat = tris.triangles[i];
        const bool raised = std::max({flat.p0.y, flat.p1.y, flat.p2.y}) >= kAtGround;
        const bool pier = info.part == uint32_t(SurfacePart::Pier);
        auto streetLift = [&](Vec3f p) {
            if (raised && !(pier && p.y < kAtGround))
                if (const std::optional<float> deck = bridges.liftAt(p.x, p.z)) return *deck;
            return terrain.heightAt(p.x, p.z);
        };
        pieces.clear();
        liftStreetTriangle(flat, streetLift, edge, pieces);
        for (const Triangle& t : pieces) lifted.add(t, info);
    }
    tris = std::move(lifted);
    for (WallRecord& w : mesh.walls) {
        const Levels& l = levels.at(w.object);
        if (w.origin.y <= l.bottom + kBaseTolerance) {
            // Down to the lowest ground, the cell grid kept where it was: floors count from the entrance.
            const float drop = l.entrance - l.base;
            w.origin.y += l.base - l.bottom;
            w.height += drop;
            w.gridV += drop;
        } else {
            w.origin.y += l.entrance;
        }
    }
    for (LampRecord& lamp : mesh.lamps) {
        const std::optional<float> deck = lamp.base.y >= kAtGround ? bridges.liftAt(lamp.base.x, lamp.base.z) : std::nullopt;
        lamp.base.y += deck ? *deck : terrain.heightAt(lamp.base.x, lamp.base.z);
    }
    for (TreeRecord& tree : mesh.trees) tree.base.y += terrain.heightAt(tree.base.x, tree.base.z);
    mesh.forests = forestTilesOnTerrain(mesh.forests, terrain);
    // The framing follows the ground under each piece; the city's bounds take every building's lift.
    for (Bounds3f& piece : mesh.framingPieces) {
        if (piece.empty()) continue;
        float lo, hi;
        terrain.rangeIn(piece.lo.x, piece.lo.z, piece.hi.x, piece.hi.z, lo, hi);
        piece.lo.y += lo;
        piece.hi.y += hi;
    }
    if (!mesh.cityBounds.empty()) {
        float lo, hi;
        terrain.rangeIn(mesh.cityBounds.lo.x, mesh.cityBounds.lo.z, mesh.cityBounds.hi.x, mesh.cityBounds.hi.z, lo, hi);
        mesh.cityBounds.lo.y += lo;
        mesh.cityBounds.hi.y += hi;
    }
}

} // namespace urbis
