// The sets of kinds and features the CUDA render kernel is compiled for (host+device, no CUDA
// needed): a scene runs the first set that covers it. One kernel for every scene carried the code
// of terrain, trees, planets, clouds and the photon camera pass into every frame, in registers,
// local memory and instruction cache (docs/gpu_notes.md § One render kernel per scene content).
// The list is short on purpose: each entry is one more copy of the megakernel to compile.
#pragma once

#include "scene/scene_features.h"

#include <cstdint>

namespace urbis {

/// Stored triangles and the ground: the city meshed (--geometry plain), no costly leaves.
inline constexpr SceneFeatures kTriangleCityFeatures = kKindFeature<Triangle> | kKindFeature<GroundRecord>;
/// A procedural city: walls and lamps (costly leaves).
inline constexpr SceneFeatures kCityFeatures = kTriangleCityFeatures | kKindFeature<WallRecord> | kKindFeature<LampRecord>;
/// The render kernels' sets, smallest first; each ends in a set that covers any scene of its kind of
/// leaves: everything without costly kinds, then everything.
inline constexpr SceneFeatures kRenderVariants[] = {
    kTriangleCityFeatures,
    kCityFeatures,
    kCityFeatures | kKindFeature<TreeRecord> | kKindFeature<ForestRecord>,
    kAllFeatures & ~kCostlyKindFeatures,
    kAllFeatures,
};
inline constexpr uint32_t kRenderVariantCount = sizeof(kRenderVariants) / sizeof(kRenderVariants[0]);

/// The index into kRenderVariants of the kernel that runs a render of `features`: the first set
/// that holds them all.
constexpr uint32_t renderVariantFor(SceneFeatures features) {
    for (uint32_t i = 0; i < kRenderVariantCount; ++i)
        if (hasFeatures(kRenderVariants[i], features)) return i;
    return kRenderVariantCount - 1;   // unreachable: the last set holds everything
}

/// Whether a kernel of `features` takes the costly leaves' traversal (SceneView::costlyLeaves).
URBIS_HD constexpr bool renderVariantHasCostlyLeaves(SceneFeatures features) { return (features & kCostlyKindFeatures) != 0; }

} // namespace urbis
