#include "fem/linear_solver.h"

#include "errors/errors.h"

#include <petscksp.h>
#include <sstream>
#include <string>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
void check(PetscErrorCode code, const std::string& what)
{
  if (code != 0)
    throw SolverFailure("PETSc " + what, "error code " + std::to_string(code));
}

// The rigid-body modes of elasticity as PETSc vectors, orthonormalised (MatNullSpaceCreate
// requires it). Built by hand: deal.II 9.4 has no helper and MatNullSpaceCreateRigidBody
// would need the DoFs of each node stored contiguously.
template <int dim>
MatNullSpace rigid_body_modes(const PETScWrappers::MPI::SparseMatrix& matrix,
                              const std::vector<Point<dim>>& support_points,
                              const std::vector<unsigned int>& dof_component,
                              MPI_Comm mpi_communicator)
{
  constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
  const auto range = matrix.local_range();
  Point<dim> centre;
  for (const auto& p : support_points)
    centre += p / static_cast<double>(support_points.size());
  std::vector<Vec> modes(n_modes);
  for (unsigned int k = 0; k < n_modes; ++k)
  {
    check(MatCreateVecs(matrix, &modes[k], nullptr), "MatCreateVecs");
    for (PetscInt i = range.first; i < static_cast<PetscInt>(range.second); ++i)
    {
      const unsigned int c = dof_component[i];
      const Tensor<1, dim> x = support_points[i] - centre;
      double value = 0;
      if (k < dim)
        value = (c == k) ? 1. : 0.;
      else
      {
        const unsigned int axis = (dim == 2) ? 2 : (k == 3 ? 2 : k - 4);
        const unsigned int p = (axis + 1) % 3, q = (axis + 2) % 3;
        if (c == p)
          value = -(q < dim ? x[q] : 0.);
        else if (c == q)
          value = p < dim ? x[p] : 0.;
      }
      check(VecSetValue(modes[k], i, value, INSERT_VALUES), "VecSetValue");
    }
    check(VecAssemblyBegin(modes[k]), "VecAssemblyBegin");
    check(VecAssemblyEnd(modes[k]), "VecAssemblyEnd");
    for (unsigned int j = 0; j < k; ++j)
    {
      PetscScalar dot;
      check(VecDot(modes[k], modes[j], &dot), "VecDot");
      check(VecAXPY(modes[k], -dot, modes[j]), "VecAXPY");
    }
    check(VecNormalize(modes[k], nullptr), "VecNormalize");
  }
  MatNullSpace space;
  check(MatNullSpaceCreate(mpi_communicator, PETSC_FALSE, n_modes, modes.data(), &space),
        "MatNullSpaceCreate");
  for (auto& v : modes)
    VecDestroy(&v);
  return space;
}

std::string reason_text(KSPConvergedReason reason)
{
  switch (reason)
  {
  case KSP_DIVERGED_ITS:
    return "iteration limit reached";
  case KSP_DIVERGED_PC_FAILED:
    return "factorization/preconditioner failed (singular or indefinite matrix)";
  case KSP_DIVERGED_INDEFINITE_PC:
  case KSP_DIVERGED_INDEFINITE_MAT:
    return "indefinite matrix or preconditioner";
  case KSP_DIVERGED_BREAKDOWN:
    return "Krylov breakdown";
  case KSP_DIVERGED_DTOL:
    return "residual diverged";
  default:
    return "PETSc reason " + std::to_string(static_cast<int>(reason));
  }
}
} // namespace

template <int dim>
unsigned int
solve_linear_system(const PETScWrappers::MPI::SparseMatrix& matrix,
                    PETScWrappers::MPI::Vector& solution, const PETScWrappers::MPI::Vector& rhs,
                    const LinearSolverParameters& parameters,
                    const std::vector<Point<dim>>& support_points,
                    const std::vector<unsigned int>& dof_component, MPI_Comm mpi_communicator)
{
  const std::string method = to_string(parameters.method);
  KSP ksp;
  PC pc;
  check(KSPCreate(mpi_communicator, &ksp), "KSPCreate");
  check(KSPSetOperators(ksp, matrix, matrix), "KSPSetOperators");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  MatNullSpace near_null_space = nullptr;
  switch (parameters.method)
  {
  case LinearSolverMethod::direct_mumps:
    // The condensed elasticity matrix is symmetric positive definite when every body is
    // held: Cholesky halves the factorization cost, and a zero pivot reveals a free body.
    check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    break;
  case LinearSolverMethod::cg_gamg:
    check(KSPSetType(ksp, KSPCG), "KSPSetType");
    check(PCSetType(pc, PCGAMG), "PCSetType");
    near_null_space = rigid_body_modes(matrix, support_points, dof_component, mpi_communicator);
    check(MatSetNearNullSpace(matrix, near_null_space), "MatSetNearNullSpace");
    break;
  case LinearSolverMethod::cg_boomeramg:
    check(KSPSetType(ksp, KSPCG), "KSPSetType");
    check(PCSetType(pc, PCHYPRE), "PCSetType");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
    // BoomerAMG ignores near-null spaces; nodal coarsening keeps the dim displacement
    // components of a node together instead (hypre's recommendation for elasticity).
    check(PetscOptionsSetValue(nullptr, "-pc_hypre_boomeramg_nodal_coarsen", "6"),
          "PetscOptionsSetValue");
    check(PetscOptionsSetValue(nullptr, "-pc_hypre_boomeramg_strong_threshold", "0.5"),
          "PetscOptionsSetValue");
    check(PCSetFromOptions(pc), "PCSetFromOptions");
    break;
  }
  if (parameters.method != LinearSolverMethod::direct_mumps)
  {
    check(KSPSetTolerances(ksp, parameters.relative_tolerance, 0., PETSC_DEFAULT,
                           parameters.max_iterations),
          "KSPSetTolerances");
    check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  }
  check(KSPSetUp(ksp), "KSPSetUp");
  const PetscErrorCode solve_code = KSPSolve(ksp, rhs, solution);
  KSPConvergedReason reason;
  KSPGetConvergedReason(ksp, &reason);
  PetscInt iterations = 0;
  KSPGetIterationNumber(ksp, &iterations);
  if (near_null_space)
  {
    MatSetNearNullSpace(matrix, nullptr);
    MatNullSpaceDestroy(&near_null_space);
  }
  KSPDestroy(&ksp);
  if (solve_code != 0)
    throw SolverFailure(method, "PETSc error " + std::to_string(solve_code) +
                                    " (singular matrix: a body may be free to move)");
  if (reason < 0)
    throw SolverFailure(method, reason_text(reason) + " after " + std::to_string(iterations) +
                                    " iterations");
  return parameters.method == LinearSolverMethod::direct_mumps ? 0 : iterations;
}

template unsigned int
solve_linear_system<2>(const PETScWrappers::MPI::SparseMatrix&, PETScWrappers::MPI::Vector&,
                       const PETScWrappers::MPI::Vector&, const LinearSolverParameters&,
                       const std::vector<Point<2>>&, const std::vector<unsigned int>&, MPI_Comm);
template unsigned int
solve_linear_system<3>(const PETScWrappers::MPI::SparseMatrix&, PETScWrappers::MPI::Vector&,
                       const PETScWrappers::MPI::Vector&, const LinearSolverParameters&,
                       const std::vector<Point<3>>&, const std::vector<unsigned int>&, MPI_Comm);
} // namespace gearstiff::fem
