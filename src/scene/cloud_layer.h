// A layer of clouds (host+device POD): a slab of the sky between two altitudes, over the whole world,
// whose density is Perlin-Worley fBm shaped by a coverage field and an altitude profile
// (media/cloud_density.h, docs/clouds.md). Its noise tables are arrays of scene_arrays.h
// (cloudLayers holds this record, or nothing where the sky has no clouds).
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// The altitude profile and the scale of a layer's shapes.
enum class CloudType : uint32_t {
    Cumulus,   ///< heaps: a flat base, rounded tops narrowing upwards
    Stratus,   ///< a sheet: wide, flat shapes over the whole thickness
    Uniform,   ///< a homogeneous slab of the density times the coverage (fog; the analytic tests)
};

/// Texels per side of the tileable 3D noise volume (cloudNoise) and of the coverage field (cloudCoverage).
inline constexpr uint32_t kCloudNoiseSize = 64;
inline constexpr uint32_t kCloudCoverageSize = 128;
/// Octaves of Wrenninge's multiple-scattering approximation at most.
inline constexpr uint32_t kCloudMaxOctaves = 4;

/// One texel of the noise volume: both in [0, 1].
struct CloudNoiseTexel {
    float shape;    ///< Perlin-Worley fBm: the heaps
    float detail;   ///< Worley fBm of higher frequency: erodes their edges
};

struct CloudLayer {
    float coverage = 0;          ///< 0: no clouds, 1: overcast
    CloudType type = CloudType::Cumulus;
    float bottom = 1500;         ///< metres above the world's y = 0
    float thickness = 2500;      ///< metres
    float density = 0.02f;       ///< extinction per metre where the cloud is densest
    float albedo = 0.99f;        ///< single-scattering albedo (water droplets barely absorb)
    float scale = 6000;          ///< metres of one period of the shape noise (its heaps are a quarter of it)
    float radius = 30000;        ///< metres from the world's origin over which the layer fades out
    Vec3f wind;                  ///< metres the clouds have moved: the noise is read at position - wind
    uint32_t seed = 1;
    float forwardG = 0.8f;       ///< Henyey-Greenstein g of the forward lobe
    float backwardG = -0.3f;     ///< and of the backward lobe
    float forwardWeight = 0.7f;  ///< the forward lobe's share
    /// Wrenninge's multiple scattering: octave i scatters a^i of the light, through b^i of the extinction,
    /// with c^i of the phase's anisotropy (octaves = 1: single scattering only).
    uint32_t octaves = 3;
    float octaveScattering = 0.5f, octaveExtinction = 0.5f, octaveAnisotropy = 0.5f;
    // Set by buildClouds (media/cloud_build.h): the coverage field's tiling.
    float coverageCell = 125;    ///< metres per texel of cloudCoverage (and per cell of cloudMajorants)
};

} // namespace urbis
