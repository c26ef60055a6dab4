// Times and counts of the photon integrators' passes, as both backends report them (host).
#pragma once

#include <cstdint>

namespace urbis {

/// Times (seconds; the GPU's from its events) and counts of the photon passes of one render call.
struct PhotonTimings {
    double flags = 0;      ///< the photon buffers' visibility pass
    double photons = 0;    ///< tracing photons (with their splats into the buffers)
    double grid = 0;       ///< building the photon map's hash grid
    double camera = 0;     ///< the camera passes (with the gathers or buffer look-ups)
    /// One lighting pass timed apart, as Argudo et al. measure it: the indirect light (gathers or
    /// look-ups) of every pixel's first non-specular hit, found beforehand, with the call's last photons.
    /// Not part of the frame; the latest call's.
    double lightingPass = 0;
    uint64_t photonRays = 0, stored = 0;
    uint64_t texels = 0;   ///< of the photon buffers, after the call
    uint32_t blocks = 0, blocksWithMemory = 0;
};

} // namespace urbis
