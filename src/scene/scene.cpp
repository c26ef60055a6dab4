#include "scene/scene.h"

#include "accel/split_references.h"
#include "accel/wide_bvh_build.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
    // Whole walls are their own tiles: no copy of them is made.
    const bool tiled = tileSize.slots > 0 || tileSize.floors > 0;
    const std::vector<WallRecord> tiles = tiled ? splitWallsIntoTiles(wholeWalls, tileSize) : std::vector<WallRecord>{};
    const std::vector<WallRecord>& walls = tiled ? tiles : wholeWalls;
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
    auto kindOf = [&](uint32_t prim) {
        uint32_t k = 0;
        while (prim >= first[k + 1]) ++k;
        return k;
    };

    // Street surfaces (what lies within kLowLayer of the ground) follow streets at any angle: on a
    // diagonal grid a sidewalk's or a curb's box is many times its area, so each is given several
    // references, one per piece (splitTriangleBounds); emitting triangles stay whole, since the
    // light list takes each slot's triangle once.
    float lowTop = grounds.empty() ? -FLT_MAX : FLT_MAX;
    for (const GroundRecord& g : grounds) lowTop = std::min(lowTop, g.height + kLowLayer);
    const SplitOptions split;
    auto boundsOf = [&](uint32_t prim) {
        Bounds3f box;
        const uint32_t kind = kindOf(prim);
        forEachPrimKind([&](auto k) {
            if (k.index == kind) box = primBounds(std::get<k.index>(inputs)[prim - first[k.index]]);
        });
        return box;
    };
    // The pieces of primitive `prim` (none for a kind at the root), appended to `pieces`; its cost.
    auto piecesOf = [&](uint32_t prim, std::vector<Bounds3f>& pieces) {
        uint32_t cost = 1;
        const uint32_t kind = kindOf(prim);
        forEachPrimKind([&](auto k) {
            if constexpr (kKindAtBvhRoot<k.index>) {
                static_assert(!kCostlyKind<k.index>, "a kind at the root is tested where the traversal meets it");
                return;
            }
            if (k.index != kind) return;
            cost = PrimRecord<k.index>::kBvhCost;
            const uint32_t i = prim - first[k.index];
            const auto& record = std::get<k.index>(inputs)[i];
            const Bounds3f box = primBounds(record);
            if constexpr (std::is_same_v<PrimRecord<k.index>, Triangle>) {
                const uint32_t material = mesh.info[i].material;
                const bool emits = material < materials.size() && maxComponent(materials[material].emission) > 0.0f;
                if (box.hi.y <= lowTop && !emits) {
                    splitTriangleBounds(record.p0, record.p1, record.p2, split, pieces);
                    return;
                }
            }
            pieces.push_back(box);
        });
        return cost;
    };
    // References of every primitive, in parallel: each one's count first, then its pieces in their
    // place, so that the references' order (and the BVH) is the same for any thread count.
    std::vector<uint32_t> firstRef(total + 1, 0);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(total), 4096), [&](const tbb::blocked_range<uint32_t>& r) {
        std::vector<Bounds3f> pieces;
        for (uint32_t prim = r.begin(); prim != r.end(); ++prim) {
            pieces.clear();
            piecesOf(prim, pieces);
            firstRef[prim + 1] = uint32_t(pieces.size());
        }
    });
    for (size_t prim = 0; prim < total; ++prim) firstRef[prim + 1] += firstRef[prim];
    const uint32_t refCount = firstRef[total];
    std::vector<Bounds3f> treeBounds(refCount);
    std::vector<uint32_t> treeIds(refCount), treeCosts;
    bool costly = false;
    forEachPrimKind([&](auto kind) {
        costly |= kCostlyKind<kind.index> && !std::get<kind.index>(inputs).empty();
    });
    if (costly) treeCosts.resize(refCount);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(total), 4096), [&](const tbb::blocked_range<uint32_t>& r) {
        std::vector<Bounds3f> pieces;
        for (uint32_t prim = r.begin(); prim != r.end(); ++prim) {
            pieces.clear();
            const uint32_t cost = piecesOf(prim, pieces);
            for (size_t p = 0; p < pieces.size(); ++p) {
                const uint32_t ref = firstRef[prim] + uint32_t(p);
                treeIds[ref] = prim;
                treeBounds[ref] = pieces[p];
                if (costly) treeCosts[ref] = cost;
            }
        }
    });
    std::vector<uint32_t> rootIds;
    std::vector<Bounds3f> rootBounds;
    for (uint32_t prim = 0; prim < total; ++prim)
        if (firstRef[prim + 1] == firstRef[prim]) {
            rootIds.push_back(prim);
            rootBounds.push_back(boundsOf(prim));
        }
    std::vector<uint32_t>().swap(firstRef);
    WideBvh bvh = buildWideBvh(treeBounds, BvhBuildOptions{}, treeCosts);
    std::vector<Bounds3f>().swap(treeBounds);
    std::vector<uint32_t>().swap(treeCosts);
    for (uint32_t& prim : bvh.primOrder) prim = treeIds[prim];
    std::vector<uint32_t>().swap(treeIds);
    attachLeavesAtRoot(bvh, rootIds, rootBounds);

    // Each kind's records are stored in leaf order, a split triangle once per reference: the leaves'
    // positions take the next slots of their kind (leafSlots), and slot s of kind k is record
    // s - kindStart(k). A kind's slots start after every reference of the kinds before it.
    uint32_t refs[kPrimKindCount] = {}, next[kPrimKindCount], kindStart[kPrimKindCount];
    for (uint32_t prim : bvh.primOrder) ++refs[kindOf(prim)];
    for (uint32_t k = 0, start = 0; k < kPrimKindCount; start += refs[k++]) next[k] = kindStart[k] = start;
    std::vector<uint32_t> slot(bvh.primOrder.size());
    for (size_t i = 0; i < slot.size(); ++i) slot[i] = next[kindOf(bvh.primOrder[i])]++;
    Scene scene;
    forEachPrimKind([&](auto k) {
        using Record = typename decltype(k)::Record;
        kindArray<Record>(scene).resize(refs[k.index]);
        if constexpr (std::is_same_v<Record, Triangle>) scene.triangleInfo.resize(refs[k.index]);
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, slot.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const uint32_t prim = bvh.primOrder[i], kind = kindOf(prim);
            forEachPrimKind([&](auto k) {
                if (k.index != kind) return;
                using Record = typename decltype(k)::Record;
                const uint32_t record = prim - first[k.index], at = slot[i] - kindStart[k.index];
                kindArray<Record>(scene)[at] = std::get<k.index>(inputs)[record];
                if constexpr (std::is_same_v<Record, Triangle>) scene.triangleInfo[at] = mesh.info[record];
            });
        }
    });
    scene.nodes = std::move(bvh.nodes);
    scene.leafSlots = std::move(slot);
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
