// Leaf dispatch over the kinds list (host+device): a leaf slot's kind from SceneView::kindEnd, and
// a call of f with that kind as a constant: a C++20 fold over the kind indices (as pbrt-v4's
// TaggedPointer::Dispatch), which compiles to a compare per kind and one inlined copy of each
// intersector; a kind that SceneView::features leaves out is skipped, and where a GPU kernel fixes
// the features its intersector is not compiled in. New kinds join scene/prim_kinds.h and this fold
// picks them up.
#pragma once

#include "geometry/forest_kind.h"
#include "geometry/ground_intersect.h"
#include "geometry/lamp_kind.h"
#include "geometry/terrain_intersect.h"
#include "geometry/tree_kind.h"
#include "geometry/planet_intersect.h"
#include "geometry/triangle_kind.h"
#include "geometry/wall_kind.h"

#include <utility>

namespace urbis {

/// Which kinds a dispatch may meet: a BVH leaf's bit kWideCostlyLeaf says which of the two it is.
enum class KindFilter { Cheap, Costly, Any };

template <KindFilter Filter, uint32_t I>
inline constexpr bool kKindPasses = Filter == KindFilter::Any || (Filter == KindFilter::Costly) == kCostlyKind<I>;

/// The last kind that passes `Filter`: a slot not of any earlier passing kind is of this one, which
/// saves its compare.
template <KindFilter Filter, uint32_t... I>
constexpr uint32_t lastPassingKind(std::integer_sequence<uint32_t, I...>) {
    const bool passes[] = {kKindPasses<Filter, I>...};
    uint32_t last = kNoPrimKind;
    for (uint32_t i = 0; i < sizeof...(I); ++i)
        if (passes[i]) last = i;
    return last;
}
template <KindFilter Filter>
inline constexpr uint32_t kLastPassingKind =
    lastPassingKind<Filter>(std::make_integer_sequence<uint32_t, kPrimKindCount>{});

template <KindFilter Filter, typename F, uint32_t... I>
URBIS_HD inline bool dispatchSlotOver(const SceneView& scene, uint32_t slot, F& f, std::integer_sequence<uint32_t, I...>) {
    bool result = false;
    (void)((kKindPasses<Filter, I> && hasFeatures(scene.features, SceneFeatures(1) << I) &&
            (I == kLastPassingKind<Filter> || slot < scene.kindEnd[I]) &&
            (result = f(PrimKindTag<I>{}, slot - scene.kindStart(I)), true)) ||
           ...);
    return result;
}

/// Calls f(PrimKindTag<kind>{}, index) for leaf slot `slot` of a kind passing `Filter` (index: into
/// the kind's array) and returns what f returns (bool).
template <KindFilter Filter, typename F>
URBIS_HD inline bool dispatchSlot(const SceneView& scene, uint32_t slot, F&& f) {
    return dispatchSlotOver<Filter>(scene, slot, f, std::make_integer_sequence<uint32_t, kPrimKindCount>{});
}

/// Tests leaf slot `slot` (of a kind passing `Filter`) with its kind's intersector.
template <KindFilter Filter>
URBIS_HD inline bool intersectSlot(const SceneView& scene, const TraceRay& tr, uint32_t slot, Ray& ray, PrimHit& hit,
                                   bool anyHit) {
    return dispatchSlot<Filter>(scene, slot, [&](auto kind, uint32_t index) {
        using Record = typename decltype(kind)::Record;
        const Record& record = kindArray<Record>(scene)[index];
        // A kind whose record points into other arrays (the terrain's samples) is handed the scene.
        if constexpr (requires { KindIntersector<Record>::kReadsScene; }) {
            if (!KindIntersector<Record>::intersect(scene, record, tr, ray, hit, anyHit)) return false;
        } else if (!KindIntersector<Record>::intersect(record, tr, ray, hit, anyHit)) return false;
        hit.slot = slot;
        return true;
    });
}

/// The hit of a trace as a SurfaceHit, by its kind's intersector.
URBIS_HD inline SurfaceHit surfaceOf(const SceneView& scene, const PrimHit& hit, const Ray& ray) {
    SurfaceHit out;
    dispatchSlot<KindFilter::Any>(scene, hit.slot, [&](auto kind, uint32_t index) {
        using Record = typename decltype(kind)::Record;
        out = KindIntersector<Record>::surface(scene, index, kindArray<Record>(scene)[index], hit, ray);
        out.kind = kind.index;
        out.index = index;
        return true;
    });
    return out;
}

} // namespace urbis
