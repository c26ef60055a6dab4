// What per-ray code reads by value beside the light arrays of scene_arrays.h (lights/light_build.h
// fills both): the places of each kind's lights in the list, the sky table's grid and the scalars
// that device tables cannot give the host.
#pragma once

#include "scene/light_records.h"
#include "urbis.h"

namespace urbis {

struct LightListInfo {
    uint32_t skyNu = 0, skyNv = 0;          ///< the sky table's grid (SceneView::skyTable)
    /// The first light of each kind in the list (kNoLight: none); a kind's lights are consecutive, in
    /// the order of its array, so that lamp i is light firstOfKind[lamp] + i.
    uint32_t firstOfKind[kLightKindCount];
    float colliderRadius = 0;               ///< metres: the colliders sampler's sphere about each light (lights/collider_lights.h)
    float powerIntegral = 0;                ///< of the lightPower table: kept here, since device tables are not read on the host
    bool built = false;                     ///< false: the list is the implicit {sun}

    URBIS_HD constexpr LightListInfo() : firstOfKind{} {
        for (uint32_t& first : firstOfKind) first = kNoLight;
    }

    /// The first light of kind `kind`, or kNoLight. A list not built stands for {sun}: the sun is light 0.
    URBIS_HD uint32_t firstOf(uint32_t kind) const {
        if (built) return firstOfKind[kind];
        return kind == kLightKindOf<SunLight> ? 0u : kNoLight;
    }
    template <typename Light>
    URBIS_HD uint32_t first() const { return firstOf(kLightKindOf<Light>); }
};

} // namespace urbis
