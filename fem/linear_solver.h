// The linear solves of fem/: PETSc's KSP driven directly, so that the near-null space for GAMG can
// be attached to the matrix and a failed factorization or a diverged Krylov method is reported as
// a SolverFailure rather than returned as a number.
#pragma once

#include "fem/parameters.h"

#include <deal.II/base/point.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <petscksp.h>
#include <string>
#include <vector>

namespace gearstiff::fem
{
// Solves A x = b. `support_points` and `dof_component` (complete, indexed by DoF) give the
// rigid-body modes for GAMG. Returns the number of Krylov iterations (0 for MUMPS).
template <int dim>
unsigned int solve_linear_system(const dealii::PETScWrappers::MPI::SparseMatrix& matrix,
                                 dealii::PETScWrappers::MPI::Vector& solution,
                                 const dealii::PETScWrappers::MPI::Vector& rhs,
                                 const LinearSolverParameters& parameters,
                                 const std::vector<dealii::Point<dim>>& support_points,
                                 const std::vector<unsigned int>& dof_component,
                                 MPI_Comm mpi_communicator);

// A failed MUMPS factorization is not a PETSc error: PETSc records it in the factor
// (MatFactorGetError, and MUMPS' INFOG(1) < 0) and lets the solves that follow return infinities
// or fail later with a bare error code. After KSPSetUp of a PCCHOLESKY/PCLU with MUMPS: why the
// factorization failed, as the reason of a SolverFailure("direct solver (MUMPS)", ...); empty
// when it succeeded.
std::string mumps_factorization_failure(PC pc);

// MUMPS' account of its latest failure on `factor` (INFOG(1) < 0) as one line: the INFOG(1) code,
// what it means, and for a lack of memory MUMPS' estimate (INFOG(16), INFOG(17); out-of-core
// INFOG(26), INFOG(27)) against what it had (ICNTL(23), or the allocation that failed, INFOG(2)).
// `phase`: "factorization" or "solve". Empty when INFOG(1) >= 0. Same on every rank (INFOG is
// global).
std::string mumps_failure(Mat factor, const std::string& phase);

// While alive, PETSc errors are returned without printing PETSc's multi-line error message: the
// caller turns them into one SolverFailure line (the command's contract: one line on failure).
class QuietPetscErrors
{
public:
  QuietPetscErrors();
  ~QuietPetscErrors();
  QuietPetscErrors(const QuietPetscErrors&) = delete;
  QuietPetscErrors& operator=(const QuietPetscErrors&) = delete;
};
} // namespace gearstiff::fem
