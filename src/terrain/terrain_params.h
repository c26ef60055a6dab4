// The terrain's parameters, as the scene description and scene files hold them
// (docs/scene_files.md § terrain): an fBm landscape, a DEM, or both added, and how rays find it.
#pragma once

#include "base/choice.h"
#include "math/value_noise.h"
#include "scene/terrain_record.h"

#include <cstdint>
#include <string>

namespace urbis {

/// The Cambridge work's dual heightmap: a second fBm landscape (its own seed, wavelength, amplitude
/// and offset; the first's octaves, lacunarity, gain, erosion and warp) blended with the first by a
/// mask of low-frequency value noise, so that two kinds of land (hills and plains, say) alternate
/// across the terrain (terrain/dual_heightmap.h).
struct DualHeightmap {
    bool enabled = false;
    uint32_t seed = 23;
    float wavelength = 400.0f;        ///< metres, of the second fBm's first octave
    float amplitude = 60.0f;          ///< metres, of its first octave
    float offset = 40.0f;             ///< metres added to its heights
    float maskWavelength = 4000.0f;   ///< metres, of the mask's noise: the size of each kind's regions
};

/// The procedural landscape of TerrainParams::kind, and how a DEM is read between its pixels.
enum class TerrainKind { None, Fbm };
enum class DemInterpolation { Bilinear, Bicubic };

/// The choices of TerrainParams::kind, ::march and ::interpolation.
inline constexpr Choice<TerrainKind> kTerrainKinds[] = {{"none", TerrainKind::None}, {"fbm", TerrainKind::Fbm}};
inline constexpr Choice<TerrainMarch> kTerrainMarches[] = {
    {"hierarchy", TerrainMarch::Hierarchy}, {"lei", TerrainMarch::Lei}, {"reference", TerrainMarch::Reference}};
inline constexpr Choice<DemInterpolation> kDemInterpolations[] = {
    {"bilinear", DemInterpolation::Bilinear}, {"bicubic", DemInterpolation::Bicubic}};

struct TerrainParams {
    std::string kind = "none";         ///< one of kTerrainKinds: the procedural landscape (plus the DEM, if any)
    std::string dem;                   ///< a raster GDAL opens (GeoTIFF, .vrt, ...): real elevation, metres
    std::string march = "hierarchy";   ///< one of kTerrainMarches
    std::string interpolation = "bicubic";  ///< one of kDemInterpolations: of the DEM between its pixels
    FbmParams fbm;                     ///< the landscape's fBm (kind "fbm")
    DualHeightmap dual;                ///< a second fBm blended with it (kind "fbm")
    float size = 8000.0f;              ///< metres a side of the fBm landscape's grid, around the city
    float cell = 0.0f;                 ///< metres between the marched samples; 0: 4 for fBm, 2 with a DEM
    float detail = 1.5f;               ///< metres: amplitude of the fBm added below a DEM's resolution
    float fade = 300.0f;               ///< metres over which the heights fall to 0 at the grid's border
    float sandLevel = 2.0f, snowLevel = 520.0f, rockSlope = 0.35f;   ///< materials (TerrainRecord)
    float leiA = 0.05f, leiB = 0.002f, leiC = 0.4f;                  ///< the Cambridge step (TerrainRecord)
    uint32_t leiBisections = 8;
    float referenceStep = 0.25f;       ///< metres, of the reference march

    bool hasFbm() const { return choiceNamed(kTerrainKinds, kind) == TerrainKind::Fbm; }
    bool enabled() const { return hasFbm() || !dem.empty(); }
};

} // namespace urbis
