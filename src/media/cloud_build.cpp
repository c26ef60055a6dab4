#include "media/cloud_build.h"

#include "media/cloud_density.h"
#include "media/cloud_noise.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace urbis {

namespace {

/// Replaces each value by its rank among all of them, over [0, 1] (ties by index: deterministic).
void rankInPlace(std::vector<float>& values) {
    std::vector<uint32_t> order(values.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return values[a] < values[b] || (values[a] == values[b] && a < b);
    });
    const float last = float(values.size() - 1);
    for (size_t r = 0; r < order.size(); ++r) values[order[r]] = float(r) / last;
}

} // namespace

std::vector<CloudNoiseTexel> buildCloudNoise(uint32_t seed) {
    constexpr uint32_t n = kCloudNoiseSize;
    std::vector<float> shape(size_t(n) * n * n), detail(shape.size());
    // Slices in parallel, each texel its own: the same volume for any thread count.
    tbb::parallel_for(uint32_t(0), n, [&](uint32_t z) {
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const Vec3f u = Vec3f{float(x), float(y), float(z)} / float(n);
                const size_t i = (size_t(z) * n + y) * n + x;
                // Billowy Perlin fBm dilated by Worley fBm (Schneider 2015): the Worley cells make the
                // heaps, the Perlin noise joins and roughens them.
                const float perlin = fabsf(2.0f * tiledPerlinFbm(u, 4, 4, hash2(seed, 1)) - 1.0f);
                const float worley = tiledWorleyFbm(u, 4, 3, hash2(seed, 2));
                shape[i] = worley + (1.0f - perlin) * (1.0f - worley) * 0.5f;
                detail[i] = tiledWorleyFbm(u, 8, 3, hash2(seed, 3));
            }
    });
    rankInPlace(shape);
    std::vector<CloudNoiseTexel> volume(shape.size());
    for (size_t i = 0; i < volume.size(); ++i) volume[i] = {shape[i], detail[i]};
    return volume;
}

std::vector<float> buildCloudCoverage(const CloudLayer& layer) {
    constexpr uint32_t n = kCloudCoverageSize;
    std::vector<float> field(size_t(n) * n, layer.coverage);
    if (layer.type == CloudType::Uniform) return field;
    for (uint32_t z = 0; z < n; ++z)
        for (uint32_t x = 0; x < n; ++x)
            field[size_t(z) * n + x] = tiledPerlinFbm(Vec3f{float(x), 0.0f, float(z)} / float(n), 8, 3, hash2(layer.seed, 4));
    rankInPlace(field);
    // Where the heaps stand (Schneider 2015's weather map): the share `coverage` of the ground, the
    // texels of the highest ranks, has coverage, rising from 0 at the heaps' edges to 1 over a ramp of
    // ranks that is widest at middling coverage (round heaps) and vanishes at 1 (overcast).
    const float c = layer.coverage, ramp = 0.7f * c * (1.0f - c) + 0.02f;
    for (float& r : field) r = std::clamp((r - (1.0f - c)) / ramp, 0.0f, 1.0f);
    return field;
}

std::vector<float> buildCloudMajorants(const CloudLayer& layer, const std::vector<float>& coverage) {
    constexpr int32_t n = int32_t(kCloudCoverageSize);
    std::vector<float> majorants(coverage.size());
    for (int32_t z = 0; z < n; ++z)
        for (int32_t x = 0; x < n; ++x) {
            // The field is bilinear over the cell: its largest value is at a corner.
            float most = 0;
            for (int c = 0; c < 4; ++c) most = std::max(most, coverage[tiledTexel(x + (c & 1), z + (c >> 1), 0, n)]);
            // A Uniform layer's density is the density times the coverage; the others' reaches the density.
            const float bound = layer.type == CloudType::Uniform ? most : (most > 0.0f ? 1.0f : 0.0f);
            majorants[size_t(z) * n + x] = layer.density * bound;
        }
    return majorants;
}

void buildClouds(Scene& scene, const CloudLayer& layer) {
    scene.cloudLayers.clear();
    scene.cloudNoise.clear();
    scene.cloudCoverage.clear();
    scene.cloudMajorants.clear();
    if (!(layer.coverage > 0.0f)) return;
    CloudLayer built = layer;
    // One tile of the coverage field spans two periods of the shape noise: the weather changes over
    // a few heaps.
    built.coverageCell = 2.0f * layer.scale / float(kCloudCoverageSize);
    scene.cloudLayers = {built};
    if (layer.type != CloudType::Uniform) scene.cloudNoise = buildCloudNoise(layer.seed);  // a Uniform layer reads no noise
    scene.cloudCoverage = buildCloudCoverage(built);
    scene.cloudMajorants = buildCloudMajorants(built, scene.cloudCoverage);
}

} // namespace urbis
