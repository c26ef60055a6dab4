// The water's parameters (the scene file's `water` object, docs/scene_files.md): its bed's depth, the
// colour its depth gives, and the wind that makes its waves (docs/water.md).
#pragma once

#include "math/vec.h"

namespace urbis {

struct WaterOptions {
    bool enabled = true;        ///< false: no water surfaces or beds (the ground shows; a benchmark's share of the water)
    float maxDepth = 4.0f;      ///< m below the ground of the bed away from the shore
    float shelfWidth = 15.0f;   ///< m from the shore to where the bed reaches maxDepth
    /// Rise over run of a river's banks on a terrain: the ground beside a river drawn from its line rises
    /// from its surface no steeper than this (0.6: 31 degrees), a valley where it would cut a trench.
    float bankSlope = 0.6f;
    /// 1/m, linear RGB: a river's clear but not pure water (pure water: about 0.35, 0.06, 0.01).
    Vec3f absorption{0.45f, 0.09f, 0.06f};
    Vec3f bedAlbedo{0.22f, 0.19f, 0.14f};   ///< the bed's silt and sand
    float windSpeed = 4.0f;      ///< m/s, 10 m above the water
    float windFrom = 225.0f;     ///< degrees clockwise from north that the wind blows from (225: south-west)
};

} // namespace urbis
