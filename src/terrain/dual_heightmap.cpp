#include "terrain/dual_heightmap.h"

#include <algorithm>

namespace urbis {

float dualMask(const DualHeightmap& dual, Vec2f p) {
    const float s = 1.0f / dual.maskWavelength;
    const float n = valueNoise(dual.seed + 303u, {p.x * s, p.y * s}).value;
    const float m = std::clamp((n + 0.3f) / 0.6f, 0.0f, 1.0f);
    return m * m * (3.0f - 2.0f * m);
}

FbmParams secondLandscape(const FbmParams& first, const DualHeightmap& dual) {
    FbmParams second = first;
    second.seed = dual.seed;
    second.wavelength = dual.wavelength;
    second.amplitude = dual.amplitude;
    second.offset = dual.offset;
    return second;
}

float landscapeHeight(const TerrainParams& params, Vec2f p) {
    const float first = fbmTerrainHeight(params.fbm, p);
    if (!params.dual.enabled) return first;
    const float m = dualMask(params.dual, p);
    if (m <= 0.0f) return first;
    const float second = fbmTerrainHeight(secondLandscape(params.fbm, params.dual), p);
    return m >= 1.0f ? second : first + m * (second - first);
}

} // namespace urbis
