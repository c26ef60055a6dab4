// What the light arrays of scene_arrays.h (lights/light_build.h fills them) need beside them: the
// sizes and places that per-ray code reads by value, and the LightsView over the arrays.
#pragma once

#include "scene/light_records.h"

namespace urbis {

struct LightListInfo {
    uint32_t skyNu = 0, skyNv = 0;          ///< the sky table's grid (lightsView's skyTable)
    uint32_t sunLight = kNoLight, skyLight = kNoLight, moonLight = kNoLight;
    uint32_t firstLampLight = kNoLight, firstWallLight = kNoLight;   ///< LightsView's
    float colliderRadius = 0;               ///< LightsView::colliderRadius
    float powerIntegral = 0;                ///< of the lightPower table: kept here, since device tables are not read on the host
    bool built = false;                     ///< false: the view stands for the implicit {sun, sky}
};

/// The view over the light arrays of `arrays` (a Scene's vectors or a DeviceScene's buffers: anything
/// with data() and size()).
LightsView makeLightsView(const auto& arrays, const LightListInfo& info) {
    if (!info.built) return LightsView{};
    LightsView v;
    v.built = true;
    v.records = arrays.lightRecords.data();
    v.count = uint32_t(arrays.lightRecords.size());
    v.power = piecewiseConstant1DView(arrays.lightPower.data(), arrays.lightPower.size(), info.powerIntegral);
    v.surfaces = arrays.emissiveSurfaces.data();
    v.triangles = arrays.triangleLights.data();
    v.emitterTriangles = arrays.emitterTriangles.data();
    v.emitterCount = uint32_t(arrays.emitterTriangles.size());
    v.bvhNodes = arrays.lightBvhNodes.data();
    v.bvhNodeCount = uint32_t(arrays.lightBvhNodes.size());
    v.bvhTrails = arrays.lightBvhTrails.data();
    v.infiniteLights = arrays.infiniteLights.data();
    v.infiniteCount = uint32_t(arrays.infiniteLights.size());
    if (arrays.skyTable.size() != 0) v.skyTable = PiecewiseConstant2DView{arrays.skyTable.data(), info.skyNu, info.skyNv};
    v.lampLights = arrays.lampLights.data();
    v.firstLampLight = info.firstLampLight;
    v.firstWallLight = info.firstWallLight;
    v.colliderRadius = info.colliderRadius;
    v.sunLight = info.sunLight;
    v.skyLight = info.skyLight;
    v.moonLight = info.moonLight;
    return v;
}

} // namespace urbis
