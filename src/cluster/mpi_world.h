// One process's place in an MPI job (Open MPI, `mpirun -n N urbis render ...`) and the tile queue
// that spreads one frame over the ranks. The build without MPI (mpi_world_none.cpp) refuses to join.
#pragma once

#include "film/film.h"
#include "film/pixel_rect.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace urbis {

/// Whether mpirun (Open MPI's, or a PMI/PMIx launcher) started this process: only then does urbis
/// join an MPI job, so that a plain `urbis render` never initialises MPI.
bool launchedByMpirun();

/// Membership of MPI_COMM_WORLD: MPI_Init_thread (funneled: only the thread that joined calls MPI)
/// on construction, MPI_Finalize on destruction.
class MpiWorld {
public:
    /// Joins the job. Throws InputError (usage) when urbis was built without MPI.
    MpiWorld();
    ~MpiWorld();
    MpiWorld(const MpiWorld&) = delete;
    MpiWorld& operator=(const MpiWorld&) = delete;

    int rank() const { return rank_; }
    int ranks() const { return ranks_; }
    /// The rank among those on this machine (MPI_COMM_TYPE_SHARED): which GPU a rank would take.
    int localRank() const { return localRank_; }
    bool isRoot() const { return rank_ == 0; }
    /// Ends every rank of the job with `exitCode` (MPI_Abort): for a failure on one rank, which
    /// would otherwise leave the others waiting for it.
    [[noreturn]] void abort(int exitCode) const;
    /// Waits until every rank has come here (MPI_Barrier).
    void barrier() const;

private:
    int rank_ = 0, ranks_ = 1, localRank_ = 0;
};

/// What each rank did in renderTilesAcrossRanks (complete on rank 0 only).
struct TileShare {
    std::vector<uint32_t> tilesByRank;  ///< tiles rendered by each rank, rank 0 first
    uint64_t rays = 0;                  ///< rays traced by all ranks
};

/// Renders `tiles` of `film` across the ranks of `world`: rank 0 hands the tiles out one at a time
/// to whichever rank asks next (a work queue, so that ranks of unequal speed share the frame by what
/// each manages) and renders tiles itself on a second thread; `renderTile(tile)` adds the tile's
/// samples to the calling rank's `film` and returns its rays. Each rank sends back the pixels of every
/// tile it rendered (packFilmRect), so that on return rank 0's film holds the whole frame, bit for bit
/// the film one process renders. Every rank calls it with the same tiles.
TileShare renderTilesAcrossRanks(const MpiWorld& world, const std::vector<PixelRect>& tiles, Film& film,
                                 const std::function<uint64_t(const PixelRect&)>& renderTile);

} // namespace urbis
