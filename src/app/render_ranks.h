// `mpirun -n N urbis render`: one frame's tiles spread over the ranks' CPUs, gathered on rank 0.
#pragma once

#include "app/render_device.h"
#include "cluster/mpi_world.h"

#include <cstdint>
#include <string>
#include <vector>

namespace urbis {

/// Adds `samples` of every pixel to `film` across the ranks of `world` (every rank has built the same
/// scene): tiles of tileSizeFor's side through renderTilesAcrossRanks, each rendered by renderCpu, so
/// that rank 0's film is bit for bit the one-process CPU render. Rank 0 then denoises it on its CPU
/// when `denoise`. `device` "cuda" and the photon integrators are refused (InputError, usage): their
/// passes span the whole frame. Returns the tiles each rank rendered (on rank 0; empty elsewhere).
std::vector<uint32_t> renderAcrossRanks(const MpiWorld& world, const Scene& scene, const Camera& camera, const RenderSettings& settings,
                       SampleRange samples, Film& film, bool denoise, const std::string& device,
                       RenderCounters& counters, DeviceReport& report);

} // namespace urbis
