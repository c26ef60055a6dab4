// What per-ray code sees of a scene: every array of scene_arrays.h as a view, and small records by
// value; the same on both backends.
#pragma once

#include "accel/wide_isa.h"
#include "scene/scene_arrays.h"
#include "scene/night_sky.h"
#include "scene/photon_view.h"
#include "scene/scene_features.h"
#include "scene/scene_lights.h"
#include "scene/sky.h"
#include "scene/sun.h"

namespace urbis {

struct SceneView {
#define URBIS_VIEW_MEMBER(Type, name, key) ArrayView<Type> name;
    URBIS_SCENE_ARRAYS(URBIS_VIEW_MEMBER)
#undef URBIS_VIEW_MEMBER
    /// The BVH's leaf slots of kind I are [kindEnd[I - 1], kindEnd[I]) (from 0 for kind 0): slot s
    /// is record s - kindEnd[I - 1] of the kind's array.
    uint32_t kindEnd[kPrimKindCount] = {};
    /// Whether any leaf is costly (kWideCostlyLeaf): the traversal then takes the costly leaves' path.
    bool costlyLeaves = false;
    /// The host's lane test of the BVH's nodes (hostWideIsa); each gives the same hits. The GPU's is scalar.
    WideIsa isa = WideIsa::Scalar;
    /// The kinds and features the scene may hold (scene/scene_features.h): a clear bit says it holds
    /// none of that, so per-ray code skips it; a GPU render kernel sets its own constant superset.
    SceneFeatures features = kAllFeatures;
    Sun sun;
    Sky sky;
    NightSky night;                      ///< the moon (a disk like the sun) and the stars
    LightListInfo lights;                ///< beside the light arrays: each kind's place in the list (not built: {sun})
    PhotonsView photons;                 ///< the photon pass's map or buffers (photon integrators only)

    /// The first leaf slot of kind I.
    URBIS_HD uint32_t kindStart(uint32_t i) const { return i == 0 ? 0u : kindEnd[i - 1]; }
};

/// The view of a scene's arrays, host vectors or device buffers alike (anything with the members of
/// scene_arrays.h, each with data() and size()).
SceneView makeSceneView(const auto& arrays, const Sun& sun, const Sky& sky, const NightSky& night,
                        const LightListInfo& lights) {
    SceneView view;
#define URBIS_VIEW_ARRAY(Type, name, key) view.name = {arrays.name.data(), uint32_t(arrays.name.size())};
    URBIS_SCENE_ARRAYS(URBIS_VIEW_ARRAY)
#undef URBIS_VIEW_ARRAY
    uint32_t end = 0;
    view.features = 0;
    forEachPrimKind([&](auto kind) {
        const uint32_t count = uint32_t(kindArray<typename decltype(kind)::Record>(arrays).size());
        end += count;
        view.kindEnd[kind.index] = end;
        view.costlyLeaves |= kCostlyKind<kind.index> && count > 0;
        if (count > 0) view.features |= SceneFeatures(1) << kind.index;
    });
    view.isa = hostWideIsa();
    if (arrays.cloudLayers.size() > 0) view.features |= kCloudsFeature;   // buildClouds keeps a layer only with coverage
    view.sun = sun;
    view.sky = sky;
    view.night = night;
    view.lights = lights;
    return view;
}

} // namespace urbis
