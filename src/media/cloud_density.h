// The density of a cloud layer (host+device): the coverage field says where clouds stand, the
// altitude profile how they swell and narrow with height, the Perlin-Worley shape noise their heaps,
// the Worley detail noise erodes their edges. After Schneider, "The Real-time Volumetric Cloudscapes
// of Horizon: Zero Dawn" (SIGGRAPH 2015 course) and Hillaire, "Physically Based Sky, Atmosphere and
// Cloud Rendering in Frostbite" (SIGGRAPH 2016 course), evaluated from the tables buildClouds makes
// (media/cloud_build.h), which both backends read as they are.
#pragma once

#include "scene/scene_view.h"

namespace urbis {

/// The tables a layer's density reads (scene_arrays.h): the noise volume, the coverage field and the
/// coverage field's per-cell majorants.
struct CloudTables {
    ArrayView<CloudNoiseTexel> noise;   ///< kCloudNoiseSize^3, x fastest, tiling
    ArrayView<float> coverage;          ///< kCloudCoverageSize^2 over the layer's (x, z), x fastest, tiling
    ArrayView<float> majorants;         ///< per coverage cell: the largest extinction (per metre) in its column
};

/// The scene's cloud tables.
URBIS_HD inline CloudTables cloudTables(const SceneView& scene) {
    return {scene.cloudNoise, scene.cloudCoverage, scene.cloudMajorants};
}

/// Whether the scene has a cloud layer that makes clouds (its record is cloudLayers[0]).
URBIS_HD inline bool hasClouds(const SceneView& scene) {
    return hasFeatures(scene.features, kCloudsFeature) && scene.cloudLayers.size > 0 && scene.cloudLayers[0].coverage > 0.0f;
}

/// (x - lo) / (hi - lo) clamped to [0, 1].
URBIS_HD inline float remapClamped(float x, float lo, float hi) { return fminf(1.0f, fmaxf(0.0f, (x - lo) / (hi - lo))); }

/// Hermite smoothstep of x from lo to hi.
URBIS_HD inline float smoothRamp(float lo, float hi, float x) {
    const float t = remapClamped(x, lo, hi);
    return t * t * (3.0f - 2.0f * t);
}

/// Where the altitude profile of `type` is 1 (heights within the layer): it rises from 0 at the
/// bottom to the plateau's start and falls from its end to 0 at the top.
URBIS_HD inline Vec2f cloudPlateau(CloudType type) {
    return type == CloudType::Cumulus ? Vec2f{0.08f, 0.3f} : Vec2f{0.15f, 0.65f};
}

/// The altitude profile of `type` at `h`, the height within the layer (0 at its bottom, 1 at its top):
/// cumulus swell fast above a flat base and narrow towards their tops; stratus fill the layer.
URBIS_HD inline float cloudProfile(CloudType type, float h) {
    const Vec2f plateau = cloudPlateau(type);
    return smoothRamp(0.0f, plateau.x, h) * (1.0f - smoothRamp(plateau.y, 1.0f, h));
}

/// Bands of the layer's height over each of which the tracking bounds the profile by its largest value.
inline constexpr int32_t kCloudBands = 8;

/// The largest value of the altitude profile of `type` over band `band` (clamped to the bands): 1
/// where the band meets the plateau, else the larger of its ends (the profile only rises, then
/// falls); 1 for a Uniform layer, which has no profile.
URBIS_HD inline float cloudProfileBound(CloudType type, int32_t band) {
    if (type == CloudType::Uniform) return 1.0f;
    band = band < 0 ? 0 : (band >= kCloudBands ? kCloudBands - 1 : band);
    const float h0 = float(band) / float(kCloudBands), h1 = float(band + 1) / float(kCloudBands);
    const Vec2f plateau = cloudPlateau(type);
    if (h1 >= plateau.x && h0 <= plateau.y) return 1.0f;
    return fmaxf(cloudProfile(type, h0), cloudProfile(type, h1));
}

/// Index of texel (x, y, z) of a tiling table `n` texels a side (x fastest), any integers.
URBIS_HD inline uint32_t tiledTexel(int32_t x, int32_t y, int32_t z, int32_t n) {
    const auto wrap = [n](int32_t i) { return uint32_t(((i % n) + n) % n); };
    return (wrap(z) * uint32_t(n) + wrap(y)) * uint32_t(n) + wrap(x);
}

/// Trilinear look-up of the noise volume at `u` (tile units: one period is 1; texel i at i / n).
URBIS_HD inline CloudNoiseTexel cloudNoiseAt(ArrayView<CloudNoiseTexel> noise, Vec3f u) {
    const int32_t n = int32_t(kCloudNoiseSize);
    const Vec3f x = u * float(n);
    const float fx = floorf(x.x), fy = floorf(x.y), fz = floorf(x.z);
    const float tx = x.x - fx, ty = x.y - fy, tz = x.z - fz;
    const int32_t ix = int32_t(fx), iy = int32_t(fy), iz = int32_t(fz);
    CloudNoiseTexel out{0, 0};
    for (int c = 0; c < 8; ++c) {
        const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        const float w = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty) * (dz ? tz : 1.0f - tz);
        const CloudNoiseTexel& t = noise[tiledTexel(ix + dx, iy + dy, iz + dz, n)];
        out.shape += w * t.shape;
        out.detail += w * t.detail;
    }
    return out;
}

/// Bilinear look-up of the coverage field at the layer's (x, z) in metres (texel i at i * cell).
URBIS_HD inline float cloudCoverageAt(const CloudLayer& layer, ArrayView<float> coverage, float x, float z) {
    const int32_t n = int32_t(kCloudCoverageSize);
    const float gx = x / layer.coverageCell, gz = z / layer.coverageCell;
    const float fx = floorf(gx), fz = floorf(gz), tx = gx - fx, tz = gz - fz;
    const int32_t ix = int32_t(fx), iz = int32_t(fz);
    const float c00 = coverage[tiledTexel(ix, iz, 0, n)], c10 = coverage[tiledTexel(ix + 1, iz, 0, n)];
    const float c01 = coverage[tiledTexel(ix, iz + 1, 0, n)], c11 = coverage[tiledTexel(ix + 1, iz + 1, 0, n)];
    return (c00 + tx * (c10 - c00)) + tz * ((c01 + tx * (c11 - c01)) - (c00 + tx * (c10 - c00)));
}

/// How the layer fades out towards its radius: 1 within 70 % of it, 0 beyond it.
URBIS_HD inline float cloudFade(const CloudLayer& layer, Vec3f position) {
    return 1.0f - smoothRamp(0.7f * layer.radius, layer.radius, sqrtf(position.x * position.x + position.z * position.z));
}

/// Extinction (per metre) of the cloud `layer` at `q` (metres in the layer's frame, the wind taken
/// off), the height `h` within the layer (0 at its bottom, 1 at its top) and the local `coverage`
/// (of the field at q), before any fade. Never more than layer.density.
URBIS_HD inline float cloudDensityOfCoverage(const CloudLayer& layer, const CloudTables& tables, Vec3f q, float h,
                                             float coverage) {
    if (!(coverage > 0.0f)) return 0.0f;
    if (layer.type == CloudType::Uniform) return layer.density * coverage;
    // Stratus spread twice as wide.
    const Vec3f u = q / (layer.type == CloudType::Stratus ? 2.0f * layer.scale : layer.scale);
    const float shape = cloudNoiseAt(tables.noise, u).shape;
    // The local coverage is the share of the shape noise's range that is cloud (the shape is uniform
    // in [0, 1]): the base density ramps from 0 at the threshold 1 - coverage to 1 at the noise's top.
    // Where the field rises towards a heap's middle, the threshold falls and the profile lets the
    // cloud reach higher: a dome over a flat base.
    const float base = remapClamped(shape * cloudProfile(layer.type, h), 1.0f - coverage, 1.0f);
    if (!(base > 0.0f)) return 0.0f;
    // Erosion: where the base is thin (the edges), the detail noise eats it; the core keeps its density.
    const float detail = cloudNoiseAt(tables.noise, u * 7.31f).detail;
    return layer.density * remapClamped(base, 0.35f * detail, 1.0f);
}

/// Extinction (per metre) of the cloud `layer` at `position` (metres, in the layer's frame: x, z
/// along the ground, y up; the layer's wind moves the pattern) and `altitude` (metres above the
/// ground: the altitude profile reads it): the world's flat layer, which passes position.y as the
/// altitude and fades out towards its radius (a planet's shell: media/cloud_shell.h). Never more than
/// cloudMajorant of its cell and band.
URBIS_HD inline float cloudDensity(const CloudLayer& layer, const CloudTables& tables, Vec3f position, float altitude) {
    const float h = (altitude - layer.bottom) / layer.thickness;
    if (!(h > 0.0f && h < 1.0f)) return 0.0f;
    const Vec3f q = position - layer.wind;
    const float coverage = cloudCoverageAt(layer, tables.coverage, q.x, q.z);
    if (!(coverage > 0.0f)) return 0.0f;
    return cloudFade(layer, position) * cloudDensityOfCoverage(layer, tables, q, h, coverage);
}

/// The majorant (per metre) of the tracking in coverage cell (ix, iz) (any integers: the field tiles)
/// and height band `band`: the cell's (cloudMajorants) times the profile's bound over the band. The
/// density never exceeds the profile (its ramp from 1 - coverage is below it), so neither the majorant.
URBIS_HD inline float cloudMajorant(const CloudLayer& layer, ArrayView<float> majorants, int32_t ix, int32_t iz, int32_t band) {
    return majorants[tiledTexel(ix, iz, 0, int32_t(kCloudCoverageSize))] * cloudProfileBound(layer.type, band);
}

} // namespace urbis
