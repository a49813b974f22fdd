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

PetscInt mumps_value(Mat factor, PetscErrorCode (*get)(Mat, PetscInt, PetscInt*), PetscInt index)
{
  PetscInt value = 0;
  check(get(factor, index, &value), "MatMumpsGet...");
  return value;
}

// MB (10^6 bytes, MUMPS' unit) of a size MUMPS gives in INFO(2)/INFOG(2): double entries,
// a negative value counting millions of them.
double entries_in_megabytes(PetscInt entries)
{
  const double count = entries < 0 ? -1e6 * static_cast<double>(entries) : entries;
  return count * sizeof(double) / 1e6;
}

// The meaning of INFOG(1) < 0 (MUMPS 5 users' guide, "Error diagnostics"), with the memory
// figures where memory was the cause.
std::string mumps_error_meaning(Mat factor, PetscInt code)
{
  const bool out_of_core = mumps_value(factor, MatMumpsGetIcntl, 22) != 0;
  std::ostringstream estimate;
  estimate << "MUMPS estimated " << mumps_value(factor, MatMumpsGetInfog, out_of_core ? 26 : 16)
           << " MB on the largest rank, "
           << mumps_value(factor, MatMumpsGetInfog, out_of_core ? 27 : 17) << " MB in all ("
           << (out_of_core ? "out-of-core" : "in-core") << ")";
  std::ostringstream text;
  text.precision(3);
  const double missing = entries_in_megabytes(mumps_value(factor, MatMumpsGetInfog, 2));
  switch (code)
  {
  case -6:
  case -10:
    return "singular matrix: a body may be free to move";
  case -40:
    return "the matrix is not positive definite";
  case -5:
  case -7:
    return "out of memory in the analysis";
  case -13:
    text << "out of memory: an allocation of " << missing << " MB failed; " << estimate.str()
         << "; out-of-core factors (-mat_mumps_icntl_22 1) need less";
    return text.str();
  case -19:
    text << "working memory above the limit ICNTL(23) = "
         << mumps_value(factor, MatMumpsGetIcntl, 23) << " MB per rank, " << missing
         << " MB short; " << estimate.str();
    return text.str();
  case -8:
  case -9:
  case -11:
  case -12:
  case -14:
  case -15:
  case -17:
  case -20:
    text << "internal workspace too small (" << missing
         << " MB short with the relaxation ICNTL(14) = "
         << mumps_value(factor, MatMumpsGetIcntl, 14) << " %; raise -mat_mumps_icntl_14); "
         << estimate.str();
    return text.str();
  default:
    return "see the error diagnostics of the MUMPS users' guide";
  }
}
} // namespace

std::string mumps_failure(Mat factor, const std::string& phase)
{
  const PetscInt code = mumps_value(factor, MatMumpsGetInfog, 1);
  if (code >= 0)
    return "";
  return phase + " failed, INFOG(1) = " + std::to_string(code) + ": " +
         mumps_error_meaning(factor, code);
}

std::string mumps_factorization_failure(PC pc)
{
  Mat factor;
  check(PCFactorGetMatrix(pc, &factor), "PCFactorGetMatrix");
  MatFactorError error;
  check(MatFactorGetError(factor, &error), "MatFactorGetError");
  const std::string failure = mumps_failure(factor, "factorization");
  if (failure.empty() && error != MAT_FACTOR_NOERROR)
    return "factorization failed (PETSc MatFactorError " + std::to_string(static_cast<int>(error)) +
           ")";
  return failure;
}

QuietPetscErrors::QuietPetscErrors()
{
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
}

QuietPetscErrors::~QuietPetscErrors()
{
  PetscPopErrorHandler();
}

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
  {
    QuietPetscErrors quiet; // a failed factorization is reported below, in one line
    check(KSPSetUp(ksp), "KSPSetUp");
  }
  const std::string factor_failure = parameters.method == LinearSolverMethod::direct_mumps
                                         ? mumps_factorization_failure(pc)
                                         : std::string();
  const PetscErrorCode solve_code = factor_failure.empty() ? KSPSolve(ksp, rhs, solution) : 0;
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
  if (!factor_failure.empty())
    throw SolverFailure("direct solver (MUMPS)", factor_failure);
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
