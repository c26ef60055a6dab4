// The scene file's "terrain" object: every field of TerrainParams with its JSON name and range, for
// visitSceneFields (description/scene_fields.h).
#pragma once

#include "terrain/terrain_params.h"

#include <span>

namespace urbis {

/// Calls the visitor `v` on every field of `t` (as visitSceneFields does).
template <typename Params, typename Visitor>
void visitTerrainFields(Params& t, Visitor& v) {
    v.choice("kind", t.kind, std::span(kTerrainKinds));
    v.text("dem", t.dem);
    v.choice("march", t.march, std::span(kTerrainMarches));
    v.choice("interpolation", t.interpolation, std::span(kDemInterpolations));
    v.number("size", t.size, 1.0f, 200000.0f);
    v.number("cell", t.cell, 0.0f, 1000.0f);
    v.number("detail", t.detail, 0.0f, 100.0f);
    v.number("fade", t.fade, 0.0f, 100000.0f);
    v.object("fbm", [&] {
        v.number("seed", t.fbm.seed, 0u, UINT32_MAX);
        v.number("octaves", t.fbm.octaves, 1u, 24u);
        v.number("wavelength", t.fbm.wavelength, 1.0f, 1e6f);
        v.number("amplitude", t.fbm.amplitude, 0.0f, 1e4f);
        v.number("lacunarity", t.fbm.lacunarity, 1.0f, 4.0f);
        v.number("gain", t.fbm.gain, 0.0f, 1.0f);
        v.number("erosion", t.fbm.erosion, 0.0f, 10.0f);
        v.number("warp", t.fbm.warp, 0.0f, 1e5f);
        v.number("offset", t.fbm.offset, -1e4f, 1e4f);
    });
    v.object("dual", [&] {
        v.boolean("enabled", t.dual.enabled);
        v.number("seed", t.dual.seed, 0u, UINT32_MAX);
        v.number("wavelength", t.dual.wavelength, 1.0f, 1e6f);
        v.number("amplitude", t.dual.amplitude, 0.0f, 1e4f);
        v.number("offset", t.dual.offset, -1e4f, 1e4f);
        v.number("mask_wavelength", t.dual.maskWavelength, 1.0f, 1e7f);
    });
    v.object("materials", [&] {
        v.number("sand_level", t.sandLevel, -1e4f, 1e4f);
        v.number("snow_level", t.snowLevel, -1e4f, 1e9f);
        v.number("rock_slope", t.rockSlope, 0.0f, 1.0f);
    });
    v.object("lei", [&] {
        v.number("a", t.leiA, 1e-4f, 100.0f);
        v.number("b", t.leiB, 0.0f, 1.0f);
        v.number("c", t.leiC, 0.0f, 1.0f);
        v.number("bisections", t.leiBisections, 0u, 64u);
    });
    v.number("reference_step", t.referenceStep, 1e-3f, 100.0f);
}

} // namespace urbis
