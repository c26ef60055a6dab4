// One process's place in an MPI job (Open MPI, `mpirun -n N urbis render ...`) and the tile queue
// that spreads one frame over the ranks. The build without MPI (mpi_world_none.cpp) refuses to join.
#pragma once

#include "cluster/tile_queue.h"
#include "cluster/tile_renderer.h"
#include "film/film.h"
#include "film/pixel_rect.h"

#include <cstdint>
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
    /// Makes every rank's `film` (of one size and layers on all ranks) rank 0's, every array bit for bit
    /// (MPI_Bcast): between the rounds of an integrator whose light pass precedes each sample, so that a
    /// tile goes on from the samples other ranks added to it.
    void broadcastFilm(Film& film) const;

private:
    int rank_ = 0, ranks_ = 1, localRank_ = 0;
};

/// Renders `tiles` of `film` across the ranks of `world`: rank 0 hands the tiles out one at a time
/// to whichever rank asks next (a TileQueue, so that ranks of unequal speed share the frame by what
/// each manages) and renders tiles itself on a second thread; each rank's `renderer` (its CPU or its
/// GPU) leaves a tile's pixels in that rank's `film`. Each rank sends back the pixels of every tile it
/// rendered (packFilmRect), so that on return rank 0's film holds the whole frame, bit for bit the
/// film one process renders with the same renderer. Every rank calls it with the same tiles. The
/// returned share (tiles by rank) is complete on rank 0 only.
TileShare renderTilesAcrossRanks(const MpiWorld& world, const std::vector<PixelRect>& tiles, Film& film,
                                 TileRenderer& renderer);

} // namespace urbis
