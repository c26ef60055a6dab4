// What the GPU tests share: skipping without a usable GPU, and data folders overridable by environment.
#pragma once

#include "cpu/cpu_renderer.h"
#include "film/image.h"
#include "gpu/gpu_backend.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

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
    bool finite = true;    ///< every GPU pixel finite (and, from renderOnBoth, as many as the CPU's)
};

inline LuminanceParity luminanceParity(const LinearImage& cpu, const LinearImage& gpu) {
    LuminanceParity p;
    for (size_t i = 0; i < cpu.pixels.size() && i < gpu.pixels.size(); ++i) {
        const double a = luminance(cpu.pixels[i]), b = luminance(gpu.pixels[i]);
        p.finite = p.finite && std::isfinite(b);
        p.mean += a / double(cpu.pixels.size());
        p.meanDiff += std::fabs(a - b) / double(cpu.pixels.size());
    }
    return p;
}

/// Renders `camera`'s view of `scene` on both backends, `width` x `height` at `spp` (the other settings
/// default), into `cpu` and `gpu`; prints and returns their luminanceParity, under `label`.
inline LuminanceParity renderOnBoth(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height, uint32_t spp,
                                    const char* label, LinearImage& cpu, LinearImage& gpu) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.spp = spp;
    RenderCounters cpuCounters, gpuCounters;
    cpu = renderCpu(scene.view(), camera, settings, false, cpuCounters);
    gpu = GpuScene::upload(scene)->render(camera, settings, gpuCounters);
    LuminanceParity parity = luminanceParity(cpu, gpu);
    parity.finite = parity.finite && cpu.pixels.size() == gpu.pixels.size();
    std::printf("%s parity: mean luminance %.4g, mean |diff| %.3g\n", label, parity.mean, parity.meanDiff);
    return parity;
}

/// The parity of two images that should agree: finite, not black, and a mean absolute difference under
/// `tolerance` times the mean luminance.
inline void expectParity(const LuminanceParity& parity, double tolerance) {
    ASSERT_TRUE(parity.finite);
    ASSERT_GT(parity.mean, 0.0);
    EXPECT_LT(parity.meanDiff, tolerance * parity.mean);
}

} // namespace urbis::test

/// Skips the current test, saying why, unless a CUDA device can run urbis's kernels.
#define URBIS_SKIP_WITHOUT_GPU()                                                  \
    do {                                                                          \
        ::urbis::GpuInfo gpuInfo_ = ::urbis::probeGpu();                          \
        if (!gpuInfo_.available) GTEST_SKIP() << gpuInfo_.reason;                 \
    } while (0)
