// Start-up of a single process without an MPI launcher (`gearstiff stiffness`, a test binary):
// Open MPI's singleton initialisation then starts a runtime daemon and probes network transports
// that one process never uses, ~0.5 s of every run (measured here: MPI_Init 0.53 s). Unless a
// launcher started the process or the user chose otherwise (existing variables are kept), ask for
// an isolated singleton with the self and shared-memory transports only: MPI_Init 0.08 s.
// Call before MPI_Init (dealii::Utilities::MPI::MPI_InitFinalize).
#pragma once

#include <cstdlib>

namespace gearstiff::fem
{
inline void prepare_mpi_start()
{
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
                        std::getenv("PMIX_RANK") != nullptr || std::getenv("PMI_RANK") != nullptr;
  if (launched)
    return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_btl", "self,vader", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_mtl", "^ofi", 0);
  setenv("OMPI_MCA_osc", "^ucx", 0);
}
} // namespace gearstiff::fem
