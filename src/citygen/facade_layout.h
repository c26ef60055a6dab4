// One footprint edge -> one procedural wall record: the wall's frame in the world, its margins and
// its grid of floors x slots (host).
#pragma once

#include "citygen/facade_style.h"
#include "scene/wall_record.h"

namespace urbis {

/// Walls lower or narrower than this (metres) stay plain.
inline constexpr float kMinFacadeHeight = 3.0f, kMinFacadeWidth = 2.0f;

/// What a wall needs to know of its building besides its edge.
struct WallContext {
    const Building* building = nullptr;
    FacadeStyle style;
    uint32_t object = 0;           ///< building index + 1
    uint32_t wallMaterial = 0;
    uint32_t facadeMaterials = 0;  ///< first of FacadeMaterial::Count
    /// Flat roofs' parapets ride on the wall records (--geometry roofs=procedural), else they are
    /// stored triangles.
    bool proceduralParapets = true;
    /// Chances in 255ths that a room and a shop window are lit (WallRecord's; citygen/window_schedule.h).
    uint8_t litChance = 77, shopLitChance = 77;
};

/// The wall on the footprint edge from `a` to `b` (city plane, metres) between heights `bottom` and
/// `top`, whose outside is to the right of a -> b when `outsideRight` (the outer ring of a
/// counter-clockwise footprint) or to its left. `depthInside` is how deep the building is behind
/// the edge (rooms reach at most 0.4 of it). `parapetHeight` is how far below the top a flat roof's
/// deck lies behind a parapet (0: no parapet): the top floor's rooms end below it. Returns false,
/// leaving `out` alone, when the wall is too small for a facade (it then stays a plain quad).
bool layoutWall(const WallContext& context, Vec2d a, Vec2d b, bool outsideRight, float bottom, float top,
                float depthInside, float parapetHeight, uint32_t wallIndex, WallRecord& out);

} // namespace urbis
