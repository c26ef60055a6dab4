// The terrain's parameters, as the scene description and scene files hold them
// (docs/scene_files.md § terrain): an fBm landscape, a DEM, or both added, and how rays find it.
#pragma once

#include "math/value_noise.h"

#include <cstdint>
#include <string>

namespace urbis {

struct TerrainParams {
    std::string kind = "none";         ///< "none" or "fbm": the procedural landscape (plus the DEM, if any)
    std::string dem;                   ///< a raster GDAL opens (GeoTIFF, .vrt, ...): real elevation, metres
    std::string march = "hierarchy";   ///< one of kTerrainMarches
    std::string interpolation = "bicubic";  ///< of the DEM between its pixels: "bilinear" or "bicubic"
    FbmParams fbm;                     ///< the landscape's fBm (kind "fbm")
    float size = 8000.0f;              ///< metres a side of the fBm landscape's grid, around the city
    float cell = 0.0f;                 ///< metres between the marched samples; 0: 4 for fBm, 2 with a DEM
    float detail = 1.5f;               ///< metres: amplitude of the fBm added below a DEM's resolution
    float fade = 300.0f;               ///< metres over which the heights fall to 0 at the grid's border
    float sandLevel = 2.0f, snowLevel = 520.0f, rockSlope = 0.35f;   ///< materials (TerrainRecord)
    float leiA = 0.05f, leiB = 0.002f, leiC = 0.4f;                  ///< the Cambridge step (TerrainRecord)
    uint32_t leiBisections = 8;
    float referenceStep = 0.25f;       ///< metres, of the reference march

    bool enabled() const { return kind == "fbm" || !dem.empty(); }
};

/// The choices of TerrainParams::kind, ::march (in TerrainMarch order) and ::interpolation.
inline constexpr const char* kTerrainKinds[] = {"none", "fbm"};
inline constexpr const char* kTerrainMarches[] = {"hierarchy", "lei", "reference"};
inline constexpr const char* kDemInterpolations[] = {"bilinear", "bicubic"};

} // namespace urbis
