// The fBm landscape's height with the Cambridge work's dual heightmap: two fBm landscapes blended by
// a low-frequency mask (host: the terrain's grid is sampled from it at build time).
#pragma once

#include "terrain/terrain_params.h"

namespace urbis {

/// How much of the second landscape lies at `p` (metres): 0 or 1 over most of the plane, a smooth
/// step between where the mask's value noise (wavelength dual.maskWavelength) crosses [-0.3, 0.3].
float dualMask(const DualHeightmap& dual, Vec2f p);

/// The second landscape's fBm: `first` with dual's seed, wavelength, amplitude and offset.
FbmParams secondLandscape(const FbmParams& first, const DualHeightmap& dual);

/// The landscape's height at `p`: fbmTerrainHeight of `params.fbm`, or with params.dual enabled
/// (1 - m) h1 + m h2, h2 the second landscape's and m = dualMask.
float landscapeHeight(const TerrainParams& params, Vec2f p);

} // namespace urbis
