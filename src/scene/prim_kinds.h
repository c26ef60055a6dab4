// The primitive kinds a BVH leaf can hold, in one list (host+device). Each kind is a POD record
// with its bounds (primBounds) and BVH cost (Record::kBvhCost) beside it in scene/, and an
// intersector in geometry/ (KindIntersector); the leaf dispatch there folds over this list.
// docs/architecture.md says how to add a kind.
#pragma once

#include "scene/forest_record.h"
#include "scene/ground_record.h"
#include "scene/lamp_record.h"
#include "scene/terrain_record.h"
#include "scene/tree_record.h"
#include "scene/planet_record.h"
#include "scene/triangle.h"
#include "scene/wall_record.h"

#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

namespace urbis {

template <typename... Records>
struct PrimKindList {
    static constexpr uint32_t count = sizeof...(Records);
    using Tuple = std::tuple<Records...>;
};

/// Every kind, by record; its place in the list is its kind index (SurfaceHit::kind), and the BVH's
/// leaf slots of each kind follow those of the kinds before it.
using PrimKinds =
    PrimKindList<Triangle, WallRecord, GroundRecord, LampRecord, TerrainRecord, TreeRecord, PlanetRecord, ForestRecord>;
inline constexpr uint32_t kPrimKindCount = PrimKinds::count;
/// SurfaceHit::kind of no hit.
inline constexpr uint32_t kNoPrimKind = 0xffu;

/// The record of kind `I`.
template <uint32_t I>
using PrimRecord = std::tuple_element_t<I, PrimKinds::Tuple>;

template <typename Record, uint32_t... I>
constexpr uint32_t primKindOf(std::integer_sequence<uint32_t, I...>) {
    const bool same[] = {std::is_same_v<Record, PrimRecord<I>>...};
    for (uint32_t i = 0; i < sizeof...(I); ++i)
        if (same[i]) return i;
    return kNoPrimKind;
}
/// The kind index of `Record`.
template <typename Record>
inline constexpr uint32_t kPrimKindOf = primKindOf<Record>(std::make_integer_sequence<uint32_t, kPrimKindCount>{});

/// Whether kind `I`'s leaves are costly (kWideCostlyLeaf: each primitive alone, tested deferred on the GPU).
template <uint32_t I>
inline constexpr bool kCostlyKind = PrimRecord<I>::kBvhCost > 1;

/// Whether kind `I` hangs from the BVH's root rather than being built into the tree: a record that
/// says so (the ground: see attachLeavesAtRoot).
template <uint32_t I>
inline constexpr bool kKindAtBvhRoot = [] {
    if constexpr (requires { PrimRecord<I>::kBvhAtRoot; }) return PrimRecord<I>::kBvhAtRoot;
    else return false;
}();

/// The tag a fold over the kinds passes: the kind index as a constant.
template <uint32_t I>
struct PrimKindTag {
    static constexpr uint32_t index = I;
    using Record = PrimRecord<I>;
};

/// Calls f(PrimKindTag<I>{}) for every kind I, in order (host code: builds, accounting).
template <typename F>
constexpr void forEachPrimKind(F&& f) {
    [&]<uint32_t... I>(std::integer_sequence<uint32_t, I...>) {
        (f(PrimKindTag<I>{}), ...);
    }(std::make_integer_sequence<uint32_t, kPrimKindCount>{});
}

} // namespace urbis
