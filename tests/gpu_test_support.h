// What the GPU tests share: skipping without a usable GPU, and data folders overridable by environment.
#pragma once

#include "gpu/gpu_backend.h"

#include <gtest/gtest.h>

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

} // namespace urbis::test

/// Skips the current test, saying why, unless a CUDA device can run urbis's kernels.
#define URBIS_SKIP_WITHOUT_GPU()                                                  \
    do {                                                                          \
        ::urbis::GpuInfo gpuInfo_ = ::urbis::probeGpu();                          \
        if (!gpuInfo_.available) GTEST_SKIP() << gpuInfo_.reason;                 \
    } while (0)
