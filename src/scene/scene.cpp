#include "scene/scene.h"

#include "scene/prim_ref.h"

#include <stdexcept>

namespace urbis {

namespace {

/// Metres by which a tile's box reaches past an edge it shares with another tile of its wall, so
/// that rounding in the box test can never lose a ray exactly on the shared edge.
constexpr float kTileOverlap = 0.01f;
/// What testing a wall costs against a triangle, for the BVH's surface area heuristic. At the
/// default cost of 1 leaves held several walls (all of a small building's) and every ray into the
/// leaf tested each of them; 4, 8 and 16 were measured on the H100 (docs/gpu_notes.md): equal on
/// the generated city, 16 best on San Francisco.
constexpr uint32_t kWallCostInTriangles = 16;
static_assert(kWallCostInTriangles > 1, "walls go in costly leaves, which traceMixed tests deferred");

/// The start of run k of n equal runs over `count` cells.
int runStart(int count, int runs, int k) { return int(int64_t(count) * k / runs); }

} // namespace

std::vector<WallRecord> splitWallsIntoTiles(const std::vector<WallRecord>& walls, WallTileSize size) {
    std::vector<WallRecord> tiles;
    tiles.reserve(walls.size());
    const int maxSlots = size.slots > 0 ? size.slots : 0xffff, maxFloors = size.floors > 0 ? size.floors : 0xffff;
    for (const WallRecord& wall : walls) {
        const int slots = wall.tileSlotEnd() - wall.slot0, floors = wall.tileFloorEnd() - wall.floor0;
        const int nu = slots > 0 ? (slots + maxSlots - 1) / maxSlots : 1;
        const int nv = floors > 0 ? (floors + maxFloors - 1) / maxFloors : 1;
        for (int b = 0; b < nv; ++b)
            for (int a = 0; a < nu; ++a) {
                WallRecord tile = wall;
                tile.slot0 = uint16_t(wall.slot0 + runStart(slots, nu, a));
                tile.slotEnd = uint16_t(wall.slot0 + runStart(slots, nu, a + 1));
                tile.floor0 = uint16_t(wall.floor0 + runStart(floors, nv, b));
                tile.floorEnd = uint16_t(wall.floor0 + runStart(floors, nv, b + 1));
                if (nu == 1) tile.slotEnd = wall.slotEnd;     // keep "to the end" (and an empty grid) as it was
                if (nv == 1) tile.floorEnd = wall.floorEnd;
                tiles.push_back(tile);
            }
    }
    return tiles;
}

Bounds3f wallTileBounds(const WallRecord& wall) {
    const float u0 = wall.tileReachU0() - (wall.slot0 > 0 ? kTileOverlap : 0.0f);
    const float u1 = wall.tileReachU1() + (wall.tileSlotEnd() < int(wall.slots) ? kTileOverlap : 0.0f);
    const float v0 = wall.tileV0() - (wall.floor0 > 0 ? kTileOverlap : 0.0f);
    const float v1 = wall.tileV1() + (wall.tileFloorEnd() < int(wall.floors) ? kTileOverlap : 0.0f);
    Bounds3f b;
    for (int k = 0; k < 8; ++k)
        b.extend(wall.worldFromWall(k & 1 ? u1 : u0, k & 2 ? v1 : v0, k & 4 ? wall.depthFront : -wall.reachBack()));
    return b;
}

Scene Scene::build(const TriangleMesh& mesh, std::vector<Material> materials, const std::vector<WallRecord>& wholeWalls,
                   WallTileSize tileSize) {
    const std::vector<WallRecord> walls = splitWallsIntoTiles(wholeWalls, tileSize);
    if (mesh.size() > kPrimIndexMask || walls.size() > kPrimIndexMask)
        throw std::length_error("scene: more than 2^28 primitives of one kind");
    std::vector<Bounds3f> bounds(mesh.size() + walls.size());
    for (size_t i = 0; i < mesh.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        bounds[i].extend(t.p0);
        bounds[i].extend(t.p1);
        bounds[i].extend(t.p2);
    }
    for (size_t i = 0; i < walls.size(); ++i) bounds[mesh.size() + i] = wallTileBounds(walls[i]);
    std::vector<uint32_t> costs;
    if (!walls.empty()) {
        costs.assign(bounds.size(), 1u);
        std::fill(costs.begin() + std::ptrdiff_t(mesh.size()), costs.end(), kWallCostInTriangles);
    }
    Bvh bvh = buildBvh(bounds, BvhBuildOptions{}, costs);
    Scene scene;
    scene.nodes = std::move(bvh.nodes);
    scene.triangles.reserve(mesh.size());
    scene.info.reserve(mesh.size());
    scene.walls.reserve(walls.size());
    if (!walls.empty()) scene.primRefs.reserve(bvh.primOrder.size());
    for (uint32_t prim : bvh.primOrder) {
        if (prim < mesh.size()) {
            if (!walls.empty()) scene.primRefs.push_back(makePrimRef(PrimKind::Triangle, uint32_t(scene.triangles.size())));
            scene.triangles.push_back(mesh.triangles[prim]);
            scene.info.push_back(mesh.info[prim]);
        } else {
            scene.primRefs.push_back(makePrimRef(PrimKind::Wall, uint32_t(scene.walls.size())));
            scene.walls.push_back(walls[prim - mesh.size()]);
        }
    }
    scene.materials = std::move(materials);
    return scene;
}

SceneView Scene::view() const {
    return makeSceneView(nodes, triangles, info, primRefs, walls, materials, ground, sun, sky, lights.view());
}

SceneMemory Scene::memory() const {
    return SceneMemory{triangles.size() * sizeof(Triangle), info.size() * sizeof(TriangleInfo),
                       walls.size() * sizeof(WallRecord),  primRefs.size() * sizeof(uint32_t),
                       materials.size() * sizeof(Material), nodes.size() * sizeof(BvhNode)};
}

} // namespace urbis
