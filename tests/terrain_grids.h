// Small synthetic terrains for the tests of what stands on a terrain.
#pragma once

#include "scene/terrain_field.h"

#include <vector>

namespace urbis::test {

/// A field of samples 2 m apart over [-100, 100]^2 with heights h(x, z).
template <typename Height>
TerrainField fieldOf(Height h) {
    std::vector<float> heights;
    for (int j = 0; j <= 100; ++j)
        for (int i = 0; i <= 100; ++i) heights.push_back(h(-100.0f + 2.0f * float(i), -100.0f + 2.0f * float(j)));
    return TerrainField::fromSamples(-100, -100, 2, 101, 101, std::move(heights));
}

} // namespace urbis::test
