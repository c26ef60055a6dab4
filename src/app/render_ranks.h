// `mpirun -n N urbis render`: one frame's tiles spread over the ranks' CPUs or GPUs, gathered on rank 0.
#pragma once

#include "app/render_device.h"
#include "cluster/mpi_world.h"

#include <cstdint>
#include <string>
#include <vector>

namespace urbis {

/// The CUDA device of this rank under mpirun: its local rank (the ranks on its machine) modulo the
/// machine's device count, one GPU per rank. InputError (device) where the machine has none.
int gpuOfRank(const MpiWorld& world);

/// Adds `samples` of every pixel to `film` across the ranks of `world` (every rank has built the same
/// scene): tiles through renderTilesAcrossRanks, each rendered by renderCpu (`device` "cpu" or "auto":
/// tiles of tileSizeFor's side) or, with "cuda", on the rank's GPU (gpuOfRank; tiles of up to
/// kGpuTileSide), so that rank 0's film is bit for bit the one-process render on that device. Rank 0
/// then denoises it when `denoise`, on its GPU or its CPU as one process would. The photon integrators
/// are refused (InputError, usage): their passes span the whole frame. Returns the tiles each rank
/// rendered (on rank 0; empty elsewhere).
std::vector<uint32_t> renderAcrossRanks(const MpiWorld& world, const Scene& scene, const Camera& camera, const RenderSettings& settings,
                       SampleRange samples, Film& film, bool denoise, const std::string& device,
                       RenderCounters& counters, DeviceReport& report);

} // namespace urbis
