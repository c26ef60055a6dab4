// The light interface (host+device): one light of the list (scene/light_records.h: LightKinds)
// sampled from a shading point, and the pdf of a direction that reached it by other means. A fold
// over the kinds' list dispatches on the record's kind, as the leaf dispatch does on primitive kinds
// (geometry/prim_dispatch.h); each kind's functions live in its own header, included here.
#pragma once

#include "lights/emissive_surface_light.h"
#include "lights/lamp_light.h"
#include "lights/moon_light.h"
#include "lights/sky_light.h"
#include "lights/sun_light.h"
#include "lights/window_light.h"

#include <utility>

namespace urbis {

template <typename F, uint32_t... I>
URBIS_HD inline auto dispatchLightOver(uint32_t kind, F& f, std::integer_sequence<uint32_t, I...>) {
    decltype(f(LightKindTag<0>{})) result{};
    (void)(((I + 1 == kLightKindCount || kind == I) && (result = f(LightKindTag<I>{}), true)) || ...);
    return result;
}

/// Calls f(LightKindTag<kind>{}) and returns what it returns: a C++20 fold over the kinds, one compare
/// per kind but the last (which a kind that is none of the others is) and one inlined copy of each.
template <typename F>
URBIS_HD inline auto dispatchLight(uint32_t kind, F&& f) {
    return dispatchLightOver(kind, f, std::make_integer_sequence<uint32_t, kLightKindCount>{});
}

template <typename Pred, uint32_t... I>
constexpr uint32_t lightKindMaskOver(Pred pred, std::integer_sequence<uint32_t, I...>) {
    return ((pred(LightKindTag<I>{}) ? 1u << I : 0u) | ... | 0u);
}
/// The kinds for which `pred(LightKindTag<I>{})` holds, as bits, so that a trait of a kind known only at
/// run time is a shift.
template <typename Pred>
constexpr uint32_t lightKindMask(Pred pred) {
    return lightKindMaskOver(pred, std::make_integer_sequence<uint32_t, kLightKindCount>{});
}
inline constexpr uint32_t kMisWeighedLightKinds = lightKindMask([](auto k) { return decltype(k)::Light::kMisWeighs; });
inline constexpr uint32_t kPickDrawLightKinds = lightKindMask([](auto k) { return decltype(k)::Light::kPickDraw; });
inline constexpr uint32_t kPointDrawLightKinds = lightKindMask([](auto k) { return decltype(k)::Light::kPointDraws; });
inline constexpr uint32_t kInfiniteLightKinds = lightKindMask([](auto k) { return decltype(k)::Light::kInfinite; });

/// Whether kind `kind`'s light samples are weighed by MIS against BSDF sampling (Light::kMisWeighs).
URBIS_HD inline bool lightKindMisWeighs(uint32_t kind) { return ((kMisWeighedLightKinds >> kind) & 1u) != 0; }
/// Whether kind `kind`'s sample reads its first number (Light::kPickDraw: a pick among its parts)
/// and its other two (Light::kPointDraws: a point or direction). Numbers are drawn only where they
/// choose something, since each draw is a hash.
URBIS_HD inline bool lightKindPicks(uint32_t kind) { return ((kPickDrawLightKinds >> kind) & 1u) != 0; }
URBIS_HD inline bool lightKindPlaces(uint32_t kind) { return ((kPointDrawLightKinds >> kind) & 1u) != 0; }

/// Samples `light` as seen from `from` with three uniform numbers. Returns false when it gives
/// nothing there (a disabled sun, an edge-on surface, no lit window found).
URBIS_HD inline bool sampleLight(const SceneView& scene, const LightRecord& light, Vec3f from, float u0, float u1,
                                 float u2, LightSample& s) {
    return dispatchLight(light.kind, [&](auto kind) {
        return decltype(kind)::Light::sample(scene, light, from, u0, u1, u2, s);
    });
}

/// Solid-angle pdf with which sampleLight(light) returns the unit direction `dir`, when that
/// direction reaches the light at `distance` where its surface makes cosine `cosLight` with `dir`
/// (those two matter for surfaces only); `from` is the shading point, which a wall's windows need.
URBIS_HD inline float lightPdf(const SceneView& scene, const LightRecord& light, Vec3f dir, float distance,
                               float cosLight, Vec3f from = {}) {
    return dispatchLight(light.kind, [&](auto kind) {
        return decltype(kind)::Light::pdf(scene, light, from, dir, distance, cosLight);
    });
}

} // namespace urbis
