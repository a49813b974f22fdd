// The linear solves of fem/: PETSc's KSP driven directly, so that the near-null space for GAMG can
// be attached to the matrix and a failed factorization or a diverged Krylov method is reported as
// a SolverFailure rather than returned as a number.
#pragma once

#include "fem/parameters.h"

#include <deal.II/base/point.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
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
} // namespace gearstiff::fem
