// GoogleTest main for tests that use deal.II/PETSc: MPI (and PETSc) initialised once for all
// tests; only rank 0 prints, so `mpiexec -np 2` output stays readable.
#include "fem/blas_start.h"
#include "fem/mpi_start.h"

#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  gearstiff::fem::select_blas_kernels();
  gearstiff::fem::prepare_mpi_start();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  // GEARSTIFF_TEST_ALL_RANKS=1 keeps every rank's output, to see a failure of rank 1 alone.
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0 &&
      std::getenv("GEARSTIFF_TEST_ALL_RANKS") == nullptr)
  {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
