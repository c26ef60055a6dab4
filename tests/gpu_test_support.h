// What the GPU tests share: skipping without a usable GPU, data folders overridable by environment, and
// the comparisons of images and ray batches between the backends.
#pragma once

#include "cpu/cpu_renderer.h"
#include "film/image.h"
#include "geometry/scene_intersect.h"
#include "gpu/gpu_backend.h"
#include "math/hash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace urbis::test {

/// The folder named by environment variable `name` if set, else the compiled-in default.
inline std::string dataDir(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value && *value ? std::string(value) : std::string(fallback);
}

/// The Bavarian village extract that osmnx's documentation ships (always there in CI).
inline std::string villageFile() {
    return dataDir("URBIS_OSMNX_DATA", URBIS_OSMNX_DATA) + "/planet_10.068,48.135_10.071,48.137.osm";
}

/// Downtown San Francisco, present where the shared data folder is.
inline std::string sanFranciscoFile() { return dataDir("URBIS_SHARED_DATA", URBIS_SHARED_DATA) + "/sf_downtown_2023.osm.pbf"; }

/// Per-pixel luminance of a CPU and a GPU image of one view: their means and the mean absolute difference.
struct LuminanceParity {
    double mean = 0;       ///< the CPU image's
    double meanDiff = 0;
    size_t pixels = 0;
    size_t off = 0;        ///< pixels whose luminance differs by more than the relative bound luminanceParity was given
    bool finite = true;    ///< every GPU pixel finite (and, from renderOnBoth, as many as the CPU's)
};

/// The parity of `gpu` against `cpu`; a pixel is off where it differs by more than `offBy` of the CPU's luminance.
inline LuminanceParity luminanceParity(const LinearImage& cpu, const LinearImage& gpu, double offBy = 1e-3) {
    LuminanceParity p;
    p.pixels = cpu.pixels.size();
    for (size_t i = 0; i < cpu.pixels.size() && i < gpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(gpu.pixels[i]);
        p.finite = p.finite && std::isfinite(b);
        p.mean += a / double(cpu.pixels.size());
        p.meanDiff += std::fabs(a - b) / double(cpu.pixels.size());
        p.off += std::fabs(a - b) > offBy * std::fmax(a, 1e-6);
    }
    return p;
}

/// Renders `camera`'s view of `scene` with `settings` on both backends into `cpu` and `gpu`; prints and
/// returns their luminanceParity (pixels off by more than `offBy`), under `label`.
inline LuminanceParity renderOnBoth(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                                    const char* label, LinearImage& cpu, LinearImage& gpu, double offBy = 1e-3) {
    RenderCounters cpuCounters, gpuCounters;
    cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    gpu = GpuScene::upload(scene)->render(camera, settings, gpuCounters);
    LuminanceParity parity = luminanceParity(cpu, gpu, offBy);
    parity.finite = parity.finite && cpu.pixels.size() == gpu.pixels.size();
    std::printf("%s parity: mean luminance %.4g, mean |diff| %.3g, %zu of %zu pixels off by > %g; rays cpu %llu gpu %llu\n",
                label, parity.mean, parity.meanDiff, parity.off, parity.pixels, offBy,
                (unsigned long long)cpuCounters.rays, (unsigned long long)gpuCounters.rays);
    return parity;
}

/// renderOnBoth, `width` x `height` at `spp` (the other settings default).
inline LuminanceParity renderOnBoth(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height, uint32_t spp,
                                    const char* label, LinearImage& cpu, LinearImage& gpu) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.spp = spp;
    return renderOnBoth(scene, camera, settings, label, cpu, gpu);
}

/// The parity of two images that should agree: finite, not black, a mean absolute difference under
/// `tolerance` times the mean luminance, and at most `offFraction` of the pixels off.
inline void expectParity(const LuminanceParity& parity, double tolerance, double offFraction = 1.0) {
    ASSERT_TRUE(parity.finite);
    ASSERT_GT(parity.mean, 0.0);
    EXPECT_LT(parity.meanDiff, tolerance * parity.mean);
    EXPECT_LE(double(parity.off), offFraction * double(parity.pixels));
}

/// Parity of renders whose paths part ways between the backends (clouds: every tracking step compares
/// a random number with a density the GPU's approximate arithmetic rounds otherwise, and a parted path
/// differs as an independent sample does): renders `camera`'s view of `scene` on both and once more on
/// the CPU with the next seed; the images' mean luminance must agree within 1 % and the mean absolute
/// pixel difference be at most 1.15 times the two CPU renders' (the GPU parts from the CPU no more
/// than an independent render does).
inline void expectParityOfIndependentRenders(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                                             const char* label) {
    RenderCounters cpuCounters, gpuCounters;
    const LinearImage cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    const LinearImage img = GpuScene::upload(scene)->render(camera, settings, gpuCounters);
    RenderSettings otherSeed = settings;
    otherSeed.seed = settings.seed + 1;
    const LinearImage independent = renderCpu(scene.view(), camera, otherSeed, false, cpuCounters);
    ASSERT_EQ(img.pixels.size(), cpu.pixels.size());
    double sumCpu = 0, sumGpu = 0, sumDiff = 0, sumNoise = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(img.pixels[i]);
        ASSERT_TRUE(std::isfinite(b)) << "pixel " << i;
        sumCpu += a;
        sumGpu += b;
        sumDiff += std::fabs(a - b);
        sumNoise += std::fabs(a - double(luminance(independent.pixels[i])));
    }
    const double n = double(cpu.pixels.size()), mean = sumCpu / n;
    std::printf("%s parity: mean luminance cpu %.5f gpu %.5f, mean |diff| %.3g (%.2f%%), between CPU seeds %.3g\n", label,
                mean, sumGpu / n, sumDiff / n, 100.0 * sumDiff / n / mean, sumNoise / n);
    ASSERT_GT(mean, 1e-4) << "the image is black";
    EXPECT_NEAR(sumGpu / n, mean, 0.01 * mean);
    EXPECT_LT(sumDiff, 1.15 * sumNoise);
}

/// How the closest hits and occlusions of a ray batch compare between the backends.
struct HitParity {
    size_t kindHits = 0;     ///< CPU hits of the kind asked about
    size_t differ = 0;       ///< rays whose hit differs in validity, kind or distance
    size_t otherIndex = 0;   ///< rays that hit another record of the same kind at the same distance (a tie)
    size_t occlusions = 0;   ///< rays whose occlusion differs
};

/// Traces `rays` through `scene` on both backends (closest hit and occlusion); prints the counts, `kind`'s hits among them.
inline HitParity traceOnBoth(const Scene& scene, const std::vector<Ray>& rays, uint32_t kind, const char* label) {
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const std::vector<SurfaceHit> gpuHits = gpu->intersect(rays);
    const std::vector<uint8_t> gpuBlocked = gpu->occluded(rays);
    const SceneView view = scene.view();
    HitParity p;
    for (size_t i = 0; i < rays.size(); ++i) {
        const SurfaceHit c = intersectScene(view, rays[i]);
        const SurfaceHit& g = gpuHits[i];
        p.kindHits += c.kind == kind;
        const bool same = c.valid() == g.valid() && c.kind == g.kind && c.t == g.t;
        if (!same && p.differ++ < 5)
            ADD_FAILURE() << label << " ray " << i << ": kind " << c.kind << "/" << g.kind << " t " << c.t << "/" << g.t;
        p.otherIndex += same && c.index != g.index;
        p.occlusions += uint8_t(occludedScene(view, rays[i])) != gpuBlocked[i];
    }
    std::printf("%s on both backends: %zu rays, %zu hit the kind, %zu differ, %zu ties, %zu occlusions differ\n", label,
                rays.size(), p.kindHits, p.differ, p.otherIndex, p.occlusions);
    return p;
}

/// `count` rays from random points of the box [originLo, originHi] towards random points of
/// [targetLo, targetHi] (each target drawn before its origin), seeded.
inline std::vector<Ray> raysBetweenBoxes(Vec3f originLo, Vec3f originHi, Vec3f targetLo, Vec3f targetHi, int count,
                                         uint32_t seed) {
    std::vector<Ray> rays;
    HashStream rng{seed};
    for (int i = 0; i < count; ++i) {
        const Vec3f target{rng.uniform(targetLo.x, targetHi.x), rng.uniform(targetLo.y, targetHi.y),
                           rng.uniform(targetLo.z, targetHi.z)};
        const Vec3f origin{rng.uniform(originLo.x, originHi.x), rng.uniform(originLo.y, originHi.y),
                           rng.uniform(originLo.z, originHi.z)};
        rays.push_back(Ray{origin, target - origin});
    }
    return rays;
}

/// traceOnBoth, expecting the same hit (kind, distance, record) and occlusion for every ray and at
/// least `minShare` of them hitting `kind`.
inline void expectSameHits(const Scene& scene, const std::vector<Ray>& rays, uint32_t kind, const char* label,
                           double minShare) {
    const HitParity parity = traceOnBoth(scene, rays, kind, label);
    EXPECT_GT(double(parity.kindHits), minShare * double(rays.size()));
    EXPECT_EQ(parity.differ, 0u);
    EXPECT_EQ(parity.otherIndex, 0u);
    EXPECT_EQ(parity.occlusions, 0u);
}

} // namespace urbis::test

/// Skips the current test, saying why, unless a CUDA device can run urbis's kernels.
#define URBIS_SKIP_WITHOUT_GPU()                                                  \
    do {                                                                          \
        ::urbis::GpuInfo gpuInfo_ = ::urbis::probeGpu();                          \
        if (!gpuInfo_.available) GTEST_SKIP() << gpuInfo_.reason;                 \
    } while (0)
