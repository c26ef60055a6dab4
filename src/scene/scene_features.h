// A scene's content as bits (host+device): which primitive kinds its BVH holds and which rare
// features a render of it uses. The GPU compiles its render kernel for a few such sets
// (gpu/render_variants.h) and runs a scene with the smallest set that covers it: the per-ray code
// tests SceneView::features where a kind or feature begins, and a kernel that fixes the set makes
// those tests constants, so the code of what the set leaves out is not in that kernel at all
// (docs/gpu_notes.md § One render kernel per scene content).
#pragma once

#include "scene/prim_kinds.h"
#include "urbis.h"

#include <cstdint>

namespace urbis {

/// A set of kinds and features: bit I is kind I of PrimKinds, the bits above the rare features.
using SceneFeatures = uint32_t;

/// The bit of kind `Record`.
template <typename Record>
inline constexpr SceneFeatures kKindFeature = SceneFeatures(1) << kPrimKindOf<Record>;
/// A cloud layer with coverage (media/cloud_tracking.h).
inline constexpr SceneFeatures kCloudsFeature = SceneFeatures(1) << kPrimKindCount;
/// A photon integrator's camera pass (integrators/photon_camera.h): a feature of the render, not the scene.
inline constexpr SceneFeatures kPhotonsFeature = SceneFeatures(1) << (kPrimKindCount + 1);
/// Every kind and feature.
inline constexpr SceneFeatures kAllFeatures = (kPhotonsFeature << 1) - 1;
/// The kinds whose leaves are costly (kCostlyKind).
inline constexpr SceneFeatures kCostlyKindFeatures = [] {
    SceneFeatures set = 0;
    forEachPrimKind([&](auto kind) {
        if (kCostlyKind<kind.index>) set |= SceneFeatures(1) << kind.index;
    });
    return set;
}();

/// Whether `set` may hold every kind and feature of `wanted`.
URBIS_HD constexpr bool hasFeatures(SceneFeatures set, SceneFeatures wanted) { return (set & wanted) == wanted; }

} // namespace urbis
