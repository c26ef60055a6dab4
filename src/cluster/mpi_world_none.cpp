// The build without MPI (CMake found no MPI, or URBIS_MPI=OFF): a process started by mpirun is refused.
#include "base/input_error.h"
#include "cluster/mpi_world.h"

#include <cstdlib>

namespace urbis {

MpiWorld::MpiWorld() {
    throw InputError("started by mpirun, but urbis was built without MPI (install libopenmpi-dev and rebuild; docs/scale.md)",
                     FailureKind::Usage);
}

MpiWorld::~MpiWorld() = default;

void MpiWorld::abort(int exitCode) const { std::exit(exitCode); }
void MpiWorld::barrier() const {}
void MpiWorld::broadcastFilm(Film&) const {}

TileShare renderTilesAcrossRanks(const MpiWorld&, const std::vector<PixelRect>&, Film&, TileRenderer&) {
    throw InputError("urbis was built without MPI", FailureKind::Usage);
}

} // namespace urbis
