// What the MPI launchers (Open MPI's mpirun, Slurm's srun with PMIx or PMI-2)
// put in the environment of the processes they start.
#include "reeb/cluster.h"

#include <cstdlib>
#include <string>

namespace reebkit::cli {

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

int launched_rank() {
  for (const char* variable : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* value = std::getenv(variable)) return std::atoi(value);
  return 0;
}

}  // namespace reebkit::cli
