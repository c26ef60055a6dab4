// What the GPU tests share: skipping without a usable GPU, and data folders overridable by environment.
#pragma once

#include "film/image.h"
#include "gpu/gpu_backend.h"

#include <gtest/gtest.h>

#include <cmath>
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
    bool finite = true;    ///< every GPU pixel finite
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

} // namespace urbis::test

/// Skips the current test, saying why, unless a CUDA device can run urbis's kernels.
#define URBIS_SKIP_WITHOUT_GPU()                                                  \
    do {                                                                          \
        ::urbis::GpuInfo gpuInfo_ = ::urbis::probeGpu();                          \
        if (!gpuInfo_.available) GTEST_SKIP() << gpuInfo_.reason;                 \
    } while (0)
