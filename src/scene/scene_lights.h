// The host arrays behind a LightsView; lights/light_build.h fills them from a scene.
#pragma once

#include "scene/light_records.h"

#include <vector>

namespace urbis {

struct SceneLights {
    std::vector<LightRecord> records;
    std::vector<float> powerTable;          ///< buildPiecewiseConstant1D over records' power
    std::vector<EmissiveSurface> surfaces;
    std::vector<TriangleLight> triangles;
    std::vector<uint32_t> lightOfMaterial;
    std::vector<float> skyTable;            ///< buildPiecewiseConstant2D over the sky, skyNu x skyNv
    uint32_t skyNu = 0, skyNv = 0;
    uint32_t sunLight = kNoLight, skyLight = kNoLight;
    bool built = false;                     ///< false: the view stands for the implicit {sun, sky}

    /// Bytes of every array.
    size_t bytes() const {
        return records.size() * sizeof(LightRecord) + powerTable.size() * sizeof(float) +
               surfaces.size() * sizeof(EmissiveSurface) + triangles.size() * sizeof(TriangleLight) +
               lightOfMaterial.size() * sizeof(uint32_t) + skyTable.size() * sizeof(float);
    }

    /// The view over these arrays, or over their device copies (anything with data() and size(),
    /// in the same order as the members above).
    LightsView view(const auto& recordsAt, const auto& powerAt, const auto& surfacesAt, const auto& trianglesAt,
                    const auto& lightOfMaterialAt, const auto& skyTableAt) const {
        if (!built) return LightsView{};
        LightsView v;
        v.built = true;
        v.records = recordsAt.data();
        v.count = uint32_t(records.size());
        if (!powerTable.empty()) v.power = piecewiseConstant1DView(powerAt.data(), powerTable.size(), powerTable.back());
        v.surfaces = surfacesAt.data();
        v.triangles = trianglesAt.data();
        v.lightOfMaterial = lightOfMaterialAt.data();
        v.materialCount = uint32_t(lightOfMaterial.size());
        if (!skyTable.empty()) v.skyTable = PiecewiseConstant2DView{skyTableAt.data(), skyNu, skyNv};
        v.sunLight = sunLight;
        v.skyLight = skyLight;
        return v;
    }
    LightsView view() const { return view(records, powerTable, surfaces, triangles, lightOfMaterial, skyTable); }
};

} // namespace urbis
