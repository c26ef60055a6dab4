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

template <typename List>
struct RecordArraysOf;
template <typename... Records>
struct RecordArraysOf<PrimKindList<Records...>> {
    using type = std::tuple<const std::vector<Records>&...>;
};
/// Each kind's records in input order, as PrimKinds lists them.
using KindRecords = RecordArraysOf<PrimKinds>::type;

/// The primitives of every kind numbered as one list: kind k's record i is primitive first[k] + i.
class Primitives {
public:
    /// `lowTop`: the height under which a triangle's box lies on a street surface (kLowLayer).
    Primitives(const KindRecords& records, const TriangleMesh& mesh, const std::vector<Material>& materials,
               float lowTop)
        : records_(records), mesh_(mesh), materials_(materials), lowTop_(lowTop) {
        size_t total = 0;
        forEachPrimKind([&](auto kind) {
            first_[kind.index] = uint32_t(total);
            total += std::get<kind.index>(records_).size();
        });
        if (total >= (size_t(1) << 31)) throw std::length_error("scene: more than 2^31 primitives");
        first_[kPrimKindCount] = uint32_t(total);
    }

    uint32_t count() const { return first_[kPrimKindCount]; }
    /// The first primitive of kind `k`.
    uint32_t first(uint32_t k) const { return first_[k]; }
    const KindRecords& records() const { return records_; }
    const TriangleMesh& mesh() const { return mesh_; }

    uint32_t kindOf(uint32_t prim) const {
        uint32_t k = 0;
        while (prim >= first_[k + 1]) ++k;
        return k;
    }

    /// Whether any primitive is of a costly kind (kCostlyKind).
    bool anyCostly() const {
        bool costly = false;
        forEachPrimKind([&](auto kind) {
            costly |= kCostlyKind<kind.index> && !std::get<kind.index>(records_).empty();
        });
        return costly;
    }

    /// The world box of primitive `prim`.
    Bounds3f boundsOf(uint32_t prim) const {
        Bounds3f box;
        const uint32_t kind = kindOf(prim);
        forEachPrimKind([&](auto k) {
            if (k.index == kind) box = primBounds(std::get<k.index>(records_)[prim - first_[k.index]]);
        });
        return box;
    }

    /// The pieces of primitive `prim` (none for a kind at the root), appended to `pieces`; its cost.
    /// Street surfaces (what lies within kLowLayer of the ground) follow streets at any angle: on a
    /// diagonal grid a sidewalk's or a curb's box is many times its area, so each is given several
    /// references, one per piece (splitTriangleBounds); emitting triangles stay whole, since the
    /// light list takes each slot's triangle once.
    uint32_t piecesOf(uint32_t prim, std::vector<Bounds3f>& pieces) const {
        uint32_t cost = 1;
        const uint32_t kind = kindOf(prim);
        forEachPrimKind([&](auto k) {
            if constexpr (kKindAtBvhRoot<k.index>) {
                static_assert(!kCostlyKind<k.index>, "a kind at the root is tested where the traversal meets it");
                return;
            }
            if (k.index != kind) return;
            cost = PrimRecord<k.index>::kBvhCost;
            const uint32_t i = prim - first_[k.index];
            const auto& record = std::get<k.index>(records_)[i];
            const Bounds3f box = primBounds(record);
            if constexpr (std::is_same_v<PrimRecord<k.index>, Triangle>) {
                const uint32_t material = mesh_.info[i].material;
                const bool emits = material < materials_.size() && maxComponent(materials_[material].emission) > 0.0f;
                if (box.hi.y <= lowTop_ && !emits) {
                    splitTriangleBounds(record.p0, record.p1, record.p2, split_, pieces);
                    return;
                }
            }
            pieces.push_back(box);
        });
        return cost;
    }

private:
    const KindRecords& records_;
    const TriangleMesh& mesh_;
    const std::vector<Material>& materials_;
    float lowTop_;
    const SplitOptions split_{};
    uint32_t first_[kPrimKindCount + 1] = {};
};

/// What the BVH is built over: the references into the tree (each a piece of a primitive) and the
/// primitives that hang from its root.
struct BvhReferences {
    std::vector<Bounds3f> treeBounds;
    std::vector<uint32_t> treeIds;     ///< the primitive of each reference
    std::vector<uint32_t> treeCosts;   ///< each reference's primitive's cost; empty when none is costly
    std::vector<uint32_t> rootIds;
    std::vector<Bounds3f> rootBounds;
};

/// The references of every primitive, in parallel: each one's count first, then its pieces in their
/// place, so that the references' order (and the BVH) is the same for any thread count.
BvhReferences referencesOf(const Primitives& prims) {
    const uint32_t total = prims.count();
    std::vector<uint32_t> firstRef(size_t(total) + 1, 0);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, total, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
        std::vector<Bounds3f> pieces;
        for (uint32_t prim = r.begin(); prim != r.end(); ++prim) {
            pieces.clear();
            prims.piecesOf(prim, pieces);
            firstRef[prim + 1] = uint32_t(pieces.size());
        }
    });
    for (size_t prim = 0; prim < total; ++prim) firstRef[prim + 1] += firstRef[prim];
    const uint32_t refCount = firstRef[total];
    BvhReferences refs;
    refs.treeBounds.resize(refCount);
    refs.treeIds.resize(refCount);
    const bool costly = prims.anyCostly();
    if (costly) refs.treeCosts.resize(refCount);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, total, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
        std::vector<Bounds3f> pieces;
        for (uint32_t prim = r.begin(); prim != r.end(); ++prim) {
            pieces.clear();
            const uint32_t cost = prims.piecesOf(prim, pieces);
            for (size_t p = 0; p < pieces.size(); ++p) {
                const uint32_t ref = firstRef[prim] + uint32_t(p);
                refs.treeIds[ref] = prim;
                refs.treeBounds[ref] = pieces[p];
                if (costly) refs.treeCosts[ref] = cost;
            }
        }
    });
    for (uint32_t prim = 0; prim < total; ++prim)
        if (firstRef[prim + 1] == firstRef[prim]) {
            refs.rootIds.push_back(prim);
            refs.rootBounds.push_back(prims.boundsOf(prim));
        }
    return refs;
}

/// The wide BVH over `refs`, its primOrder holding primitives (not references), with the root's
/// primitives attached. Frees each array of `refs` once it has served.
WideBvh buildSceneBvh(BvhReferences&& refs) {
    WideBvh bvh = buildWideBvh(refs.treeBounds, BvhBuildOptions{}, refs.treeCosts);
    std::vector<Bounds3f>().swap(refs.treeBounds);
    std::vector<uint32_t>().swap(refs.treeCosts);
    for (uint32_t& prim : bvh.primOrder) prim = refs.treeIds[prim];
    std::vector<uint32_t>().swap(refs.treeIds);
    attachLeavesAtRoot(bvh, refs.rootIds, refs.rootBounds);
    return bvh;
}

/// Stores each kind's records in the BVH's leaf order into `scene`, a split triangle once per
/// reference: the leaves' positions take the next slots of their kind (leafSlots), and slot s of kind
/// k is record s - kindStart(k). A kind's slots start after every reference of the kinds before it.
void storeInLeafOrder(const Primitives& prims, WideBvh&& bvh, Scene& scene) {
    uint32_t refs[kPrimKindCount] = {}, next[kPrimKindCount], kindStart[kPrimKindCount];
    for (uint32_t prim : bvh.primOrder) ++refs[prims.kindOf(prim)];
    for (uint32_t k = 0, start = 0; k < kPrimKindCount; start += refs[k++]) next[k] = kindStart[k] = start;
    std::vector<uint32_t> slot(bvh.primOrder.size());
    for (size_t i = 0; i < slot.size(); ++i) slot[i] = next[prims.kindOf(bvh.primOrder[i])]++;
    forEachPrimKind([&](auto k) {
        using Record = typename decltype(k)::Record;
        kindArray<Record>(scene).resize(refs[k.index]);
        if constexpr (std::is_same_v<Record, Triangle>) scene.triangleInfo.resize(refs[k.index]);
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, slot.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const uint32_t prim = bvh.primOrder[i], kind = prims.kindOf(prim);
            forEachPrimKind([&](auto k) {
                if (k.index != kind) return;
                using Record = typename decltype(k)::Record;
                const uint32_t record = prim - prims.first(k.index), at = slot[i] - kindStart[k.index];
                kindArray<Record>(scene)[at] = std::get<k.index>(prims.records())[record];
                if constexpr (std::is_same_v<Record, Triangle>) scene.triangleInfo[at] = prims.mesh().info[record];
            });
        }
    });
    scene.nodes = std::move(bvh.nodes);
    scene.leafSlots = std::move(slot);
}

} // namespace

Scene Scene::build(SceneInputs in) {
    // Whole walls are their own tiles: no copy of them is made.
    const bool tiled = in.tileSize.slots > 0 || in.tileSize.floors > 0;
    const std::vector<WallRecord> tiles =
        tiled ? splitWallsIntoTiles(in.walls, in.tileSize) : std::vector<WallRecord>{};
    const std::vector<WallRecord>& walls = tiled ? tiles : in.walls;
    const std::vector<TerrainRecord> terrains =
        in.terrain.empty() ? std::vector<TerrainRecord>{} : std::vector{in.terrain.record};
    const KindRecords records =
        std::tie(in.mesh.triangles, walls, in.grounds, in.lamps, terrains, in.trees, in.planets, in.forests);
    float lowTop = in.grounds.empty() ? -FLT_MAX : FLT_MAX;
    for (const GroundRecord& g : in.grounds) lowTop = std::min(lowTop, g.height + kLowLayer);
    const Primitives prims(records, in.mesh, in.materials, lowTop);

    Scene scene;
    storeInLeafOrder(prims, buildSceneBvh(referencesOf(prims)), scene);
    scene.materials = std::move(in.materials);
    scene.terrainData = in.terrain.data;
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
