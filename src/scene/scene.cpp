#include "scene/scene.h"

#include "accel/split_references.h"

#include <algorithm>
#include <cfloat>
#include <stdexcept>
#include <tuple>

namespace urbis {
namespace {

/// Height above the lowest ground (metres) under which a triangle's box must lie to count as a street
/// surface: up to the rails on their ballast at 0.45 m (streets/street_levels.h).
constexpr float kLowLayer = 0.5f;

} // namespace

Scene Scene::build(const TriangleMesh& mesh, std::vector<Material> materials, const std::vector<WallRecord>& wholeWalls,
                   WallTileSize tileSize, const std::vector<GroundRecord>& grounds,
                   const std::vector<LampRecord>& lamps, const std::vector<TreeRecord>& trees,
                   const TerrainField& terrain, const std::vector<PlanetRecord>& planets,
                   const std::vector<ForestRecord>& forests) {
    const std::vector<WallRecord> walls = splitWallsIntoTiles(wholeWalls, tileSize);
    // Each kind's records in input order, as PrimKinds lists them.
    const std::vector<TerrainRecord> terrains = terrain.empty() ? std::vector<TerrainRecord>{} : std::vector{terrain.record};
    const auto inputs = std::tie(mesh.triangles, walls, grounds, lamps, terrains, trees, planets, forests);
    static_assert(std::tuple_size_v<decltype(inputs)> == kPrimKindCount, "an input per kind of PrimKinds");
    // Kind k's record i is primitive first[k] + i.
    uint32_t first[kPrimKindCount + 1] = {};
    size_t total = 0;
    forEachPrimKind([&](auto kind) {
        first[kind.index] = uint32_t(total);
        total += std::get<kind.index>(inputs).size();
    });
    if (total >= (size_t(1) << 31)) throw std::length_error("scene: more than 2^31 primitives");
    first[kPrimKindCount] = uint32_t(total);

    // Street surfaces (what lies within kLowLayer of the ground) follow streets at any angle: on a
    // diagonal grid a sidewalk's or a curb's box is many times its area, so each is given several
    // references, one per piece (splitTriangleBounds); emitting triangles stay whole, since the
    // light list takes each slot's triangle once.
    float lowTop = grounds.empty() ? -FLT_MAX : FLT_MAX;
    for (const GroundRecord& g : grounds) lowTop = std::min(lowTop, g.height + kLowLayer);
    const SplitOptions split;
    std::vector<Bounds3f> treeBounds, rootBounds, pieces;
    std::vector<uint32_t> treeIds, treeCosts, rootIds;
    bool costly = false;
    forEachPrimKind([&](auto kind) {
        const auto& records = std::get<kind.index>(inputs);
        for (size_t i = 0; i < records.size(); ++i) {
            const uint32_t id = first[kind.index] + uint32_t(i);
            const Bounds3f box = primBounds(records[i]);
            if constexpr (kKindAtBvhRoot<kind.index>) {
                static_assert(!kCostlyKind<kind.index>, "a kind at the root is tested where the traversal meets it");
                rootIds.push_back(id);
                rootBounds.push_back(box);
                continue;
            }
            pieces.assign(1, box);
            if constexpr (std::is_same_v<PrimRecord<kind.index>, Triangle>) {
                const uint32_t material = mesh.info[i].material;
                const bool emits = material < materials.size() && maxComponent(materials[material].emission) > 0.0f;
                if (box.hi.y <= lowTop && !emits) {
                    pieces.clear();
                    splitTriangleBounds(records[i].p0, records[i].p1, records[i].p2, split, pieces);
                }
            }
            for (const Bounds3f& piece : pieces) {
                treeIds.push_back(id);
                treeBounds.push_back(piece);
                treeCosts.push_back(PrimRecord<kind.index>::kBvhCost);
            }
            costly |= kCostlyKind<kind.index>;
        }
    });
    BvhBuildOptions options;
    options.freeRootLanes = uint32_t(std::min<size_t>(rootIds.size(), kBvhWidth - 2));
    Bvh bvh = buildBvh(treeBounds, options, costly ? treeCosts : std::vector<uint32_t>{});
    for (uint32_t& prim : bvh.primOrder) prim = treeIds[prim];
    for (size_t i = 0; i < rootIds.size(); ++i) attachLeafAtRoot(bvh, rootIds[i], rootBounds[i]);

    // Leaves in node order take the next slots of their kind, and each kind's records are stored in
    // that order, a split triangle once per reference: slot s of kind k is record s - kindStart(k).
    Scene scene;
    scene.triangles.reserve(mesh.size());
    scene.triangleInfo.reserve(mesh.size());
    scene.walls.reserve(walls.size());
    scene.grounds.reserve(grounds.size());
    scene.lamps.reserve(lamps.size());
    scene.trees.reserve(trees.size());
    scene.planets.reserve(planets.size());
    auto kindOf = [&](uint32_t prim) {
        uint32_t k = 0;
        while (prim >= first[k + 1]) ++k;
        return k;
    };
    // A kind's slots start after every reference of the kinds before it (split triangles have several).
    uint32_t refs[kPrimKindCount] = {}, next[kPrimKindCount];
    for (uint32_t prim : bvh.primOrder) ++refs[kindOf(prim)];
    for (uint32_t k = 0, start = 0; k < kPrimKindCount; start += refs[k++]) next[k] = start;
    for (BvhNode& node : bvh.nodes)
        for (int l = 0; l < kBvhWidth; ++l) {
            const uint32_t size = node.leafSize(l);
            if (size == 0) continue;
            const uint32_t kind = kindOf(bvh.primOrder[node.child[l]]);
            for (uint32_t i = 0; i < size; ++i) {
                const uint32_t prim = bvh.primOrder[node.child[l] + i];
                if (kindOf(prim) != kind) throw std::logic_error("scene: a BVH leaf holds primitives of two kinds");
                forEachPrimKind([&](auto k) {
                    if (k.index != kind) return;
                    using Record = typename decltype(k)::Record;
                    const uint32_t record = prim - first[k.index];
                    kindArray<Record>(scene).push_back(std::get<k.index>(inputs)[record]);
                    if constexpr (std::is_same_v<Record, Triangle>) scene.triangleInfo.push_back(mesh.info[record]);
                });
            }
            node.child[l] = next[kind];
            next[kind] += size;
        }
    scene.nodes = std::move(bvh.nodes);
    scene.materials = std::move(materials);
    scene.terrainData = terrain.data;
    return scene;
}

SceneView Scene::view() const { return makeSceneView(*this, sun, sky, night, lights); }

SceneMemory Scene::memory() const {
    SceneMemory memory;
#define URBIS_MEMORY_OF(Type, name, key) memory.name = name.size() * sizeof(Type);
    URBIS_SCENE_ARRAYS(URBIS_MEMORY_OF)
#undef URBIS_MEMORY_OF
    return memory;
}

} // namespace urbis
