// Light records (host+device POD) and the list of light kinds. A light of the sampler's list is a
// kind and an index into the array of its kind; each kind's functions (sampling, pdf, power, bounds,
// photons) live in its own header in lights/, which lights/light.h folds over.
#pragma once

#include "math/vec.h"
#include "scene/lamp_record.h"

#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

namespace urbis {

template <typename... Kinds>
struct LightKindList {
    static constexpr uint32_t count = sizeof...(Kinds);
    using Tuple = std::tuple<Kinds...>;
};

struct SunLight;              ///< lights/sun_light.h: SceneView::sun, a disk of directions
struct SkyLight;              ///< lights/sky_light.h: the environment, importance-sampled from its radiance
struct MoonLight;             ///< lights/moon_light.h: SceneView::night.moon, a disk of directions as the sun
struct EmissiveSurfaceLight;  ///< lights/emissive_surface_light.h: SceneView::emissiveSurfaces[index]
struct LampLight;             ///< lights/lamp_light.h: SceneView::lampLights[index], a street lamp's point
struct WindowLight;           ///< lights/window_light.h: SceneView::walls[index], a wall record's lit windows

/// Every light kind; its place in the list is LightRecord::kind. buildLights adds each kind's lights
/// in this order, so the list's records are the sun, the sky, the moon, the emitting triangles, the
/// lamps and the walls.
using LightKinds = LightKindList<SunLight, SkyLight, MoonLight, EmissiveSurfaceLight, LampLight, WindowLight>;
inline constexpr uint32_t kLightKindCount = LightKinds::count;

/// The light kind of index `I`.
template <uint32_t I>
using LightKindAt = std::tuple_element_t<I, LightKinds::Tuple>;

template <typename Light, uint32_t... I>
constexpr uint32_t lightKindOf(std::integer_sequence<uint32_t, I...>) {
    const bool same[] = {std::is_same_v<Light, LightKindAt<I>>...};
    for (uint32_t i = 0; i < sizeof...(I); ++i)
        if (same[i]) return i;
    return kLightKindCount;
}
/// The index of light kind `Light`.
template <typename Light>
inline constexpr uint32_t kLightKindOf = lightKindOf<Light>(std::make_integer_sequence<uint32_t, kLightKindCount>{});

/// The tag a fold over the light kinds passes: the kind index as a constant.
template <uint32_t I>
struct LightKindTag {
    static constexpr uint32_t index = I;
    using Light = LightKindAt<I>;
};

/// Calls f(LightKindTag<I>{}) for every kind I, in the list's order (host code: the build).
template <typename F>
constexpr void forEachLightKind(F&& f) {
    [&]<uint32_t... I>(std::integer_sequence<uint32_t, I...>) {
        (f(LightKindTag<I>{}), ...);
    }(std::make_integer_sequence<uint32_t, kLightKindCount>{});
}

/// One light of the sampler's list.
struct LightRecord {
    uint32_t kind = 0;   ///< index into LightKinds
    uint32_t index = 0;  ///< into the array of its kind (0 for the sun, the moon and the sky)
    float power = 0;     ///< luminous flux in the renderer's units (each kind's addLights says how)
    uint32_t litCells = 0;  ///< WindowLight: the lit cells of its tile, which its sampler picks among (lights/window_light.h)
};

/// An emitting surface: triangles of one emitting material, sampled uniformly by area. It emits
/// `emission` from both sides, as materials do. buildLights makes one per emitting triangle, so that
/// the light BVH can tell near emitters from far ones (docs/lights.md § Emitting triangles).
struct EmissiveSurface {
    Vec3f emission;
    uint32_t firstTriangle = 0, triangleCount = 0;  ///< range of SceneView::triangleLights
    float area = 0;                                 ///< total, square metres
};

/// A triangle of an EmissiveSurface, with the cumulative share of its surface's area up to and
/// including it, so that a triangle is picked in proportion to its area by a binary search.
struct TriangleLight {
    Vec3f p0, p1, p2;
    float cdf = 0;
};

/// A street lamp as a light (lights/lamp_light.h): a point at its glass whose intensity follows a
/// profile by head shape, made from a LampRecord at scene build (lampEmitterOf).
struct LampEmitter {
    Vec3f position;          ///< world, metres: the glass's centre
    Vec3f intensity;         ///< at the profile's peak, renderer units (radiance x m^2, docs/lights.md § Units)
    float glassRadius = 0;   ///< the glass's radius, metres (a disc's, a globe's, a lantern's widest)
    float glassHeight = 0;   ///< a lantern's glass's height, metres; 0 for the others
    /// Shadow rays towards the point stop this far short of it, so that the lamp's own glass does
    /// not block them: the radius of a sphere about the point holding the glass.
    float clearance = 0;
    LampShape shape = LampShape::Cobra;
};

constexpr uint32_t kNoLight = 0xffffffffu;

/// A light-sampled emitting triangle: its index in SceneView::triangles and its light. Sorted by
/// triangle, so that the light a BSDF sample found is a binary search (lights/emissive_surface_light.h).
struct EmitterTriangle {
    uint32_t triangle = 0, light = 0;
};

} // namespace urbis
