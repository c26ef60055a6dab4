// The tables of a cloud layer, built on the host when the scene is prepared: the tileable noise volume,
// the coverage field and its per-cell majorants (media/cloud_density.h reads them). They are arrays of
// the scene (scene_arrays.h), so both backends read the same bytes, and --stats counts them.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace urbis {

/// The noise volume of `seed`: kCloudNoiseSize^3 texels, x fastest, tiling. Its shape channel
/// (Perlin-Worley fBm) is stored as each texel's rank among all of them, so it is uniform in [0, 1]
/// and a coverage c makes the share c of the volume cloud; its detail channel is Worley fBm of
/// twice the frequency.
std::vector<CloudNoiseTexel> buildCloudNoise(uint32_t seed);

/// The coverage field of `layer` (its coverage, type and seed): kCloudCoverageSize^2 texels of the
/// local coverage in [0, 1] over the layer's (x, z), tiling: where the heaps stand. Its Perlin fBm
/// is ranked as the shape is, so that the share layer.coverage of the ground lies under clouds; a
/// Uniform layer's is its coverage everywhere.
std::vector<float> buildCloudCoverage(const CloudLayer& layer);

/// The majorant (per metre) of each coverage cell: layer.density where any corner of the cell has
/// coverage (the density never exceeds it), 0 where none has (the tracking skips the cell).
std::vector<float> buildCloudMajorants(const CloudLayer& layer, const std::vector<float>& coverage);

/// Sets the scene's cloud layer to `layer` and builds its tables; with no coverage, clears them all
/// (no clouds, and no bytes).
void buildClouds(Scene& scene, const CloudLayer& layer);

} // namespace urbis
