#include "cluster/mpi_world.h"

#include <cstdlib>

namespace urbis {

bool launchedByMpirun() {
    // Open MPI's mpirun, PMIx launchers (Slurm's srun --mpi=pmix, prterun) and MPICH's Hydra (PMI).
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (std::getenv(variable)) return true;
    return false;
}

} // namespace urbis
