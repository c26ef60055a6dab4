// The scene file's "terrain" object: every field of TerrainParams with its JSON name, range and
// option, for visitSceneFields (description/scene_fields.h).
#pragma once

#include "description/scene_field.h"
#include "terrain/terrain_params.h"

namespace urbis {

/// Calls the visitor `v` on every field of `t` (as visitSceneFields does).
template <typename Params, typename Visitor>
void visitTerrainFields(Params& t, Visitor& v) {
    v.choice({"kind", "--terrain",
              "Terrain under the city: none (the flat ground) or fbm (a procedural landscape; with --dem, added to it)"},
             t.kind, kTerrainKinds);
    v.text({"dem", "--dem",
            "Elevation raster GDAL opens (GeoTIFF, .vrt, any CRS): real terrain under the city, metres above sea level"},
           t.dem);
    v.choice({"march", "--terrain-march",
              "How rays find the terrain: hierarchy (min/max mips, exact), lei (the Cambridge dynamic step) or "
              "reference (fixed small steps)"},
             t.march, kTerrainMarches);
    v.choice({"interpolation", "--dem-interpolation", "Of the DEM between its pixels: bilinear or bicubic"},
             t.interpolation, kDemInterpolations);
    v.number({"size", "--terrain-size", "Metres a side of the fBm landscape, around the city's centre"}, t.size, 1.0f,
             200000.0f);
    v.number({"cell", "--terrain-cell", "Metres between the marched samples; 0: 4 for fBm, 2 with a DEM"}, t.cell, 0.0f,
             1000.0f);
    v.number({"detail", "--terrain-detail", "Metres of fBm detail added below the DEM's resolution"}, t.detail, 0.0f,
             100.0f);
    v.number({"fade", "--terrain-fade", "Metres over which the heights fall to 0 at the grid's border"}, t.fade, 0.0f,
             100000.0f);
    v.object("fbm", [&] {
        v.number({"seed", "--fbm-seed", "Seed of the landscape's noise"}, t.fbm.seed, 0u, UINT32_MAX);
        v.number({"octaves", "--fbm-octaves", "Octaves summed"}, t.fbm.octaves, 1u, 24u);
        v.number({"wavelength", "--fbm-wavelength", "Metres, of the first octave"}, t.fbm.wavelength, 1.0f, 1e6f);
        v.number({"amplitude", "--fbm-amplitude", "Metres, of the first octave"}, t.fbm.amplitude, 0.0f, 1e4f);
        v.number({"lacunarity", "--fbm-lacunarity", "Frequency ratio of successive octaves"}, t.fbm.lacunarity, 1.0f, 4.0f);
        v.number({"gain", "--fbm-gain", "Amplitude ratio of successive octaves"}, t.fbm.gain, 0.0f, 1.0f);
        v.number({"erosion", "--fbm-erosion", "Derivative damping of each octave by the gradients before it"},
                 t.fbm.erosion, 0.0f, 10.0f);
        v.number({"warp", "--fbm-warp", "Metres of domain distortion by two low-frequency noises"}, t.fbm.warp, 0.0f, 1e5f);
        v.number({"offset", "--fbm-offset", "Metres added to every height"}, t.fbm.offset, -1e4f, 1e4f);
    });
    v.object("dual", [&] {
        v.boolean({"enabled", "--dual-heightmap", "Blend a second fBm landscape in by a low-frequency mask"},
                  t.dual.enabled);
        v.number({"seed", "--dual-seed", "Seed of the second landscape's noise and of the mask's"}, t.dual.seed, 0u,
                 UINT32_MAX);
        v.number({"wavelength", "--dual-wavelength", "Metres, of the second landscape's first octave"}, t.dual.wavelength,
                 1.0f, 1e6f);
        v.number({"amplitude", "--dual-amplitude", "Metres, of the second landscape's first octave"}, t.dual.amplitude,
                 0.0f, 1e4f);
        v.number({"offset", "--dual-offset", "Metres added to the second landscape's heights"}, t.dual.offset, -1e4f, 1e4f);
        v.number({"mask_wavelength", "--dual-mask-wavelength", "Metres, of the mask's noise: the size of each region"},
                 t.dual.maskWavelength, 1.0f, 1e7f);
    });
    v.object("materials", [&] {
        v.number({"sand_level", "--terrain-sand-level", "Metres below which the ground is sand"}, t.sandLevel, -1e4f, 1e4f);
        v.number({"snow_level", "--terrain-snow-level", "Metres above which gentle slopes are snow"}, t.snowLevel, -1e4f,
                 1e9f);
        v.number({"rock_slope", "--terrain-rock-slope", "1 - normal.y above which the ground is rock"}, t.rockSlope, 0.0f,
                 1.0f);
    });
    v.object("lei", [&] {
        v.number({"a", "--lei-a", "Metres: the constant of the Cambridge step a + b distance + c height"}, t.leiA, 1e-4f,
                 100.0f);
        v.number({"b", "--lei-b", "The Cambridge step's share of the distance"}, t.leiB, 0.0f, 1.0f);
        v.number({"c", "--lei-c", "The Cambridge step's share of the height above the ground"}, t.leiC, 0.0f, 1.0f);
        v.number({"bisections", "--lei-bisections", "Halvings of the last step"}, t.leiBisections, 0u, 64u);
    });
    v.number({"reference_step", "--terrain-reference-step", "Metres, of the reference march"}, t.referenceStep, 1e-3f,
             100.0f);
}

} // namespace urbis
