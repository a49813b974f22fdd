#include "fem/stiffness_factorization.h"

#include "errors/errors.h"
#include "fem/linear_solver.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <map>
#include <numeric>
#include <petscksp.h>
#include <petscmat.h>
#include <string>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
// A PETSc matrix destroyed with its scope.
struct OwnedMat
{
  Mat mat = nullptr;
  OwnedMat() = default;
  OwnedMat(const OwnedMat&) = delete;
  OwnedMat& operator=(const OwnedMat&) = delete;
  ~OwnedMat()
  {
    if (mat)
      MatDestroy(&mat);
  }
};

void check(PetscErrorCode code, const std::string& what)
{
  if (code != 0)
    throw SolverFailure("direct solver (MUMPS) " + what,
                        "PETSc error code " + std::to_string(code));
}

AffineConstraints<double> homogeneous_copy(const AffineConstraints<double>& constraints)
{
  AffineConstraints<double> homogeneous;
  homogeneous.copy_from(constraints);
  for (const auto& line : constraints.get_lines())
    homogeneous.set_inhomogeneity(line.index, 0.);
  return homogeneous;
}

// One DoF per free mode whose fixing removes that mode: pivoted elimination on the mode
// vectors, each step taking the unconstrained DoF with the largest remaining amplitude, so the
// fixed DoFs' block of the modes is well conditioned.
std::vector<types::global_dof_index> fixing_dofs(const std::vector<Vector<double>>& modes,
                                                 const AffineConstraints<double>& constraints)
{
  std::vector<Vector<double>> remaining = modes;
  std::vector<types::global_dof_index> fixed;
  for (unsigned int j = 0; j < remaining.size(); ++j)
  {
    types::global_dof_index pivot = numbers::invalid_dof_index;
    double largest = 0.;
    for (types::global_dof_index i = 0; i < remaining[j].size(); ++i)
      if (std::abs(remaining[j][i]) > largest && !constraints.is_constrained(i) &&
          std::find(fixed.begin(), fixed.end(), i) == fixed.end())
      {
        largest = std::abs(remaining[j][i]);
        pivot = i;
      }
    if (pivot == numbers::invalid_dof_index)
      throw SolverFailure("stiffness factorization",
                          "a free rigid-body mode has no unconstrained DoF to fix");
    fixed.push_back(pivot);
    for (unsigned int k = j + 1; k < remaining.size(); ++k)
      remaining[k].add(-remaining[k][pivot] / remaining[j][pivot], remaining[j]);
  }
  return fixed;
}
// The connected parts of the graph of K condensed with `constraints`: DoFs joined by a cell or
// by a constraint share a part (union-find). Every rank holds the whole mesh.
template <int dim>
std::vector<unsigned int> connected_parts(const DoFHandler<dim>& dof_handler,
                                          const AffineConstraints<double>& constraints)
{
  std::vector<unsigned int> parent(dof_handler.n_dofs());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](unsigned int i)
  {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  auto join = [&](unsigned int a, unsigned int b) { parent[root(a)] = root(b); };
  std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(dofs);
    for (const auto dof : dofs)
      join(dof, dofs[0]);
  }
  for (const auto& line : constraints.get_lines())
    for (const auto& [master, weight] : line.entries)
      join(master, line.index);
  for (unsigned int i = 0; i < parent.size(); ++i)
    parent[i] = root(i);
  return parent;
}
// `constraints` with the DoFs of fixing_dofs held as well.
AffineConstraints<double> held_constraints(const AffineConstraints<double>& constraints,
                                           const std::vector<Vector<double>>& modes)
{
  AffineConstraints<double> fixed;
  for (const auto& line : constraints.get_lines())
  {
    fixed.add_line(line.index);
    fixed.add_entries(line.index, line.entries);
    fixed.set_inhomogeneity(line.index, line.inhomogeneity);
  }
  for (const auto dof : fixing_dofs(modes, constraints))
    fixed.add_line(dof);
  fixed.close();
  return fixed;
}
} // namespace

template <int dim>
struct StiffnessFactorization<dim>::Implementation
{
  MPI_Comm mpi_communicator;
  IndexSet locally_owned;
  types::global_dof_index n_dofs = 0;
  AffineConstraints<double> homogeneous; // supports and fixed DoFs, zero inhomogeneities
  // The connected part of K (bodies, or bodies tied by constraints) of every DoF. K⁻¹ couples
  // DoFs of different parts by exact zeros, and these must not be asked of MUMPS: its selected
  // inverse entries (ICNTL(30)) on several ranks return stale values for them (MUMPS 5.5, 3D Q2
  // gear pair, 407k DoFs, 2 ranks: 2520 of 288000 entries nonzero where their mirror (K⁻¹)ᵀ entry
  // is the exact 0, and the contact Schur complement came out singular).
  std::vector<unsigned int> part;
  PETScWrappers::MPI::SparseMatrix matrix;
  KSP ksp = nullptr;
  Mat factor = nullptr; // owned by the KSP's PC
  // The dense Schur complement of the condensed K on the interface DoFs, factorized; empty
  // when not computed (several ranks, or no interface given).
  std::vector<types::global_dof_index> interface; // sorted, unconstrained DoFs
  Eigen::LLT<Eigen::MatrixXd> interface_factor;
  bool dense = false;

  // The interface DoFs that carry the condensed loads and the values of `dofs`: unconstrained
  // DoFs themselves, constrained ones through their masters.
  std::vector<types::global_dof_index>
  interface_of(const std::vector<types::global_dof_index>& dofs) const
  {
    std::vector<types::global_dof_index> result;
    for (const auto dof : dofs)
      if (const auto* entries = homogeneous.get_constraint_entries(dof))
        for (const auto& [master, weight] : *entries)
          result.push_back(master);
      else if (!homogeneous.is_constrained(dof))
        result.push_back(dof);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  ~Implementation()
  {
    if (ksp)
      KSPDestroy(&ksp);
  }

  // A call into MUMPS (a solve) with PETSc's own error message held back: on failure, MUMPS'
  // INFOG(1) and what it means, in one line.
  template <typename Call>
  void call_mumps(const Call& call, const std::string& what) const
  {
    PetscErrorCode code;
    {
      QuietPetscErrors quiet;
      code = call();
    }
    if (code == 0)
      return;
    const std::string failure = mumps_failure(factor, "solve");
    if (failure.empty())
      check(code, what);
    throw SolverFailure("direct solver (MUMPS)", failure);
  }

  // Where a load on `dof` acts after condensation (and what the value at `dof` is made of):
  // the DoF itself, or a constrained DoF's masters with their weights.
  std::vector<std::pair<types::global_dof_index, double>>
  condensed_targets(types::global_dof_index dof) const
  {
    if (const auto* entries = homogeneous.get_constraint_entries(dof))
      return *entries;
    if (homogeneous.is_constrained(dof))
      return {};
    return {{dof, 1.}};
  }

  // MUMPS's selected entries of K⁻¹ at the pattern of `transposed` (Bᵀ, MatMumpsGetInverse),
  // the solver's settings restored afterwards.
  void selected_inverse(Mat transposed, bool serial) const
  {
    // Right-hand sides per block of the solve (ICNTL(27)): with 512 instead of MUMPS's
    // automatic choice the entries of the 3D contact DoFs took 3.4 s instead of 4.9 s
    // (1026 columns, 190k DoFs, 2 ranks; 8: 10 s, 2048: 4.4 s).
    PetscInt block = 0;
    check(MatMumpsGetIcntl(factor, 27, &block), "MatMumpsGetIcntl");
    check(MatMumpsSetIcntl(factor, 27, 512), "MatMumpsSetIcntl");
    PetscErrorCode code = 0;
    const auto get_inverse = [&]()
    {
      code = MatMumpsGetInverse(factor, transposed);
      // Back to the settings of the ordinary solves: no inverse entries; several ranks keep
      // the solution distributed.
      MatMumpsSetIcntl(factor, 27, block);
      MatMumpsSetIcntl(factor, 30, 0);
      if (!serial)
        MatMumpsSetIcntl(factor, 21, 1);
      return code;
    };
    call_mumps(get_inverse, "MatMumpsGetInverse");
  }

  // (K⁻¹)_{rows, columns} of the condensed K, column by column (result[j·|rows| + i] =
  // (K⁻¹)_{rows[i], columns[j]}), on every rank. MUMPS computes selected entries of the
  // inverse (ICNTL(30)) with sparse right-hand sides and prunes the triangular solves to the
  // elimination-tree paths that lead to the wanted entries: for the contact DoFs of a 3D scene
  // (a surface layer of the mesh) far cheaper than whole solves with dense right-hand sides
  // (190k DoFs, 2 ranks: 4.0 s against 14.1 s for the same 1161 columns). Both index lists sorted.
  std::vector<double> inverse_entries(const std::vector<types::global_dof_index>& columns,
                                      const std::vector<types::global_dof_index>& rows) const
  {
    std::vector<double> result(columns.size() * rows.size(), 0.);
    if (columns.empty() || rows.empty())
      return result;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const bool serial = Utilities::MPI::n_mpi_processes(mpi_communicator) == 1;
    // Only the rows in the column's connected part of K: the others are exact zeros (see
    // `part`). Columns in chunks, so that the pattern stays small for a million DoFs.
    std::map<unsigned int, std::vector<unsigned int>> part_rows; // part → positions in rows
    for (unsigned int i = 0; i < rows.size(); ++i)
      part_rows[part[rows[i]]].push_back(i);
    const std::vector<unsigned int> no_rows;
    auto wanted = [&](types::global_dof_index column) -> const std::vector<unsigned int>&
    {
      const auto found = part_rows.find(part[column]);
      return found == part_rows.end() ? no_rows : found->second;
    };
    for (std::size_t first = 0, n_columns = 0; first < columns.size(); first += n_columns)
    {
      std::size_t n_entries = 0;
      for (n_columns = 0; first + n_columns < columns.size() && n_entries < 4'000'000; ++n_columns)
        n_entries += wanted(columns[first + n_columns]).size();
      // The pattern Bᵀ, all on rank 0: row c lists the wanted rows of column c of K⁻¹.
      const PetscInt n = root ? n_dofs : 0;
      std::vector<PetscInt> row_start(n + 1, 0), column_index;
      if (root)
      {
        for (std::size_t j = 0; j < n_columns; ++j)
          row_start[columns[first + j] + 1] = wanted(columns[first + j]).size();
        for (PetscInt i = 0; i < n; ++i)
          row_start[i + 1] += row_start[i];
        column_index.reserve(n_entries);
        for (std::size_t j = 0; j < n_columns; ++j)
          for (const unsigned int i : wanted(columns[first + j]))
            column_index.push_back(rows[i]);
      }
      std::vector<PetscScalar> values(column_index.size(), 0.);
      Mat pattern, transposed;
      if (serial)
        check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, row_start.data(),
                                        column_index.data(), values.data(), &pattern),
              "MatCreateSeqAIJWithArrays");
      else
        check(MatCreateMPIAIJWithArrays(mpi_communicator, n, n, n_dofs, n_dofs, row_start.data(),
                                        column_index.data(), values.data(), &pattern),
              "MatCreateMPIAIJWithArrays");
      check(MatCreateTranspose(pattern, &transposed), "MatCreateTranspose");
      selected_inverse(transposed, serial);
      if (root)
      {
        Mat local = pattern;
        if (!serial)
          check(MatMPIAIJGetSeqAIJ(pattern, &local, nullptr, nullptr), "MatMPIAIJGetSeqAIJ");
        const PetscScalar *entries, *start;
        check(MatSeqAIJGetArrayRead(local, &start), "MatSeqAIJGetArrayRead");
        entries = start;
        for (std::size_t j = 0; j < n_columns; ++j)
          for (const unsigned int i : wanted(columns[first + j]))
            result[(first + j) * rows.size() + i] = *entries++;
        check(MatSeqAIJRestoreArrayRead(local, &start), "MatSeqAIJRestoreArrayRead");
      }
      MatDestroy(&transposed);
      MatDestroy(&pattern);
    }
    if (!serial)
      Utilities::MPI::broadcast(result.data(), result.size(), 0, mpi_communicator);
    return result;
  }

  // Cholesky by MUMPS on `matrix` (symmetric positive definite once every body is held);
  // returns the preconditioner that holds the factor.
  PC create_cholesky_solver()
  {
    PC pc;
    check(KSPCreate(mpi_communicator, &ksp), "KSPCreate");
    check(KSPSetOperators(ksp, matrix, matrix), "KSPSetOperators");
    check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
    check(PCFactorGetMatrix(pc, &factor), "PCFactorGetMatrix");
    // Factors out of core (MUMPS ICNTL(22) = 1, files in $MUMPS_OOC_TMPDIR, else /tmp) from
    // `out_of_core_dofs` on: the 3D Q2 pair at 1.06 M DoFs on 2 ranks then peaks at 10.6 GB in
    // all (MUMPS in core: 11.1 GB for the factors alone on top of ~8 GB), for ~10 % more time at
    // 407k DoFs (27.0 s against 24.2 s, same k). PETSC_OPTIONS (-mat_mumps_icntl_22) still
    // override.
    constexpr types::global_dof_index out_of_core_dofs = 500'000;
    if (n_dofs >= out_of_core_dofs)
      check(MatMumpsSetIcntl(factor, 22, 1), "MatMumpsSetIcntl");
    return pc;
  }

  // Asks MUMPS for the dense Schur complement on the interface of `interface_dofs` where it
  // pays: MUMPS forms it as a dense root front and Eigen factorizes it again, both O(n³).
  // Measured on one rank (2D, 47k–59k DoFs): 320 and 638 interface DoFs (gear pair, single and
  // double) 0.1 s faster than the sparse inverse entries; 4443 (cycloid drive, 28 pairs) 2.8 s
  // slower for the same forces.
  void request_schur_complement(const std::vector<types::global_dof_index>& interface_dofs)
  {
    const bool serial = Utilities::MPI::n_mpi_processes(mpi_communicator) == 1;
    constexpr std::size_t max_dense_interface = 1500;
    std::vector<types::global_dof_index> candidate;
    if (serial && !interface_dofs.empty())
      candidate = interface_of(interface_dofs);
    if (candidate.empty() || candidate.size() > max_dense_interface)
      return;
    interface = std::move(candidate);
    std::vector<PetscInt> indices(interface.begin(), interface.end());
    IS is;
    check(ISCreateGeneral(PETSC_COMM_SELF, indices.size(), indices.data(), PETSC_COPY_VALUES, &is),
          "ISCreateGeneral");
    check(MatFactorSetSchurIS(factor, is), "MatFactorSetSchurIS");
    ISDestroy(&is);
  }

  // The DoFs whose values give those at `rows`: for a constrained row its masters (sorted).
  std::vector<types::global_dof_index>
  values_needed(const std::vector<types::global_dof_index>& rows) const
  {
    std::vector<types::global_dof_index> needed;
    for (const auto row : rows)
    {
      if (const auto* entries = homogeneous.get_constraint_entries(row))
        for (const auto& [master, weight] : *entries)
          needed.push_back(master);
      else if (!homogeneous.is_constrained(row))
        needed.push_back(row);
    }
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    return needed;
  }

  // (K⁻¹)_CC = S⁻¹ for the Schur complement S on the interface C: loads on C only need S. Adds
  // the responses at `rows` into `result` and returns true when every load lies on C.
  bool interface_responses(const std::vector<SparseLoad>& loads,
                           const std::vector<types::global_dof_index>& rows,
                           std::vector<std::vector<double>>& result) const
  {
    auto interface_position = [&](types::global_dof_index dof)
    { return std::lower_bound(interface.begin(), interface.end(), dof) - interface.begin(); };
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(interface.size(), loads.size());
    for (unsigned int j = 0; j < loads.size(); ++j)
      for (const auto& [dof, value] : loads[j])
        for (const auto& [target, weight] : condensed_targets(dof))
        {
          const auto k = interface_position(target);
          if (k == static_cast<long>(interface.size()) || interface[k] != target)
            return false;
          rhs(k, j) += weight * value;
        }
    const Eigen::MatrixXd solution = interface_factor.solve(rhs);
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto& [target, weight] : condensed_targets(rows[r]))
      {
        const auto k = interface_position(target);
        for (unsigned int j = 0; j < loads.size(); ++j)
          result[j][r] += weight * solution(k, j);
      }
    return true;
  }

  // C^T b: a load on a constrained DoF acts on its masters (virtual work), written into the
  // owned entries of `rhs` (every rank holds the complete load).
  void condense(const SparseLoad& load, Vec rhs) const
  {
    for (const auto& [dof, value] : load)
    {
      if (value == 0.)
        continue;
      if (const auto* entries = homogeneous.get_constraint_entries(dof))
      {
        for (const auto& [master, weight] : *entries)
          if (locally_owned.is_element(master))
            check(VecSetValue(rhs, master, weight * value, ADD_VALUES), "VecSetValue");
      }
      else if (!homogeneous.is_constrained(dof) && locally_owned.is_element(dof))
        check(VecSetValue(rhs, dof, value, ADD_VALUES), "VecSetValue");
    }
  }
};

template <int dim>
StiffnessFactorization<dim>::StiffnessFactorization(
    const ElasticSystem<dim>& system, const AffineConstraints<double>& constraints,
    const Vector<double>& point_loads, const std::vector<types::global_dof_index>& interface_dofs)
    : impl(std::make_unique<Implementation>())
{
  Timer timer(system.get_mpi_communicator(), true);
  impl->mpi_communicator = system.get_mpi_communicator();
  impl->locally_owned = system.get_dof_handler().locally_owned_dofs();
  impl->n_dofs = system.get_dof_handler().n_dofs();

  // Supports plus one fixed DoF per free rigid-body mode: a non-singular matrix whose inverse
  // is a generalized inverse of the support-condensed one.
  modes = system.free_rigid_modes(constraints);
  AffineConstraints<double> fixed = held_constraints(constraints, modes);
  impl->homogeneous = homogeneous_copy(fixed);
  impl->part = connected_parts(system.get_dof_handler(), fixed);

  PETScWrappers::MPI::Vector rhs;
  system.condensed_system(fixed, point_loads, impl->matrix, rhs);
  PC pc = impl->create_cholesky_solver();
  impl->request_schur_complement(interface_dofs);
  // A failed factorization (out of memory, singular) is no PETSc error: ask MUMPS.
  PetscErrorCode setup_code;
  {
    QuietPetscErrors quiet;
    setup_code = KSPSetUp(impl->ksp);
  }
  if (const std::string failure = mumps_factorization_failure(pc); !failure.empty())
    throw SolverFailure("direct solver (MUMPS)", failure);
  if (setup_code != 0)
    throw SolverFailure("direct solver (MUMPS)",
                        "the factorization failed (singular matrix: a body may be free to move)");
  if (!impl->interface.empty())
    factorize_interface();

  PETScWrappers::MPI::Vector solution(impl->locally_owned, impl->mpi_communicator);
  impl->call_mumps([&]() { return KSPSolve(impl->ksp, rhs, solution); }, "KSPSolve");
  ++solves;
  particular.reinit(impl->n_dofs);
  particular = Vector<double>(solution);
  fixed.distribute(particular);
  factor_seconds = timer.wall_time();
}

template <int dim>
StiffnessFactorization<dim>::~StiffnessFactorization() = default;

template <int dim>
bool StiffnessFactorization<dim>::dense_interface() const
{
  return impl->dense;
}

template <int dim>
void StiffnessFactorization<dim>::factorize_interface()
{
  Mat schur;
  MatFactorSchurStatus status;
  check(MatFactorCreateSchurComplement(impl->factor, &schur, &status),
        "MatFactorCreateSchurComplement");
  const PetscInt n = impl->interface.size();
  const PetscScalar* values;
  check(MatDenseGetArrayRead(schur, &values), "MatDenseGetArrayRead");
  Eigen::MatrixXd matrix = Eigen::Map<const Eigen::MatrixXd>(values, n, n);
  check(MatDenseRestoreArrayRead(schur, &values), "MatDenseRestoreArrayRead");
  MatDestroy(&schur);
  // For a symmetric factorization MUMPS may return one triangle only: mirror the filled one.
  const double lower = matrix.triangularView<Eigen::StrictlyLower>().toDenseMatrix().norm();
  const double upper = matrix.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().norm();
  if (upper == 0. && lower > 0.)
    matrix = matrix.selfadjointView<Eigen::Lower>();
  else if (lower == 0. && upper > 0.)
    matrix = matrix.selfadjointView<Eigen::Upper>();
  impl->interface_factor.compute(matrix);
  // The Schur complement of a positive definite matrix is positive definite; if the dense
  // factorization fails anyway, the sparse solves remain (same answer, slower).
  impl->dense = impl->interface_factor.info() == Eigen::Success;
}

template <int dim>
Vector<double> StiffnessFactorization<dim>::response(const Vector<double>& load) const
{
  SparseLoad entries;
  for (types::global_dof_index i = 0; i < load.size(); ++i)
    if (load[i] != 0.)
      entries.emplace_back(i, load[i]);
  PETScWrappers::MPI::Vector rhs(impl->locally_owned, impl->mpi_communicator);
  impl->condense(entries, rhs);
  rhs.compress(VectorOperation::add);
  PETScWrappers::MPI::Vector solution(impl->locally_owned, impl->mpi_communicator);
  impl->call_mumps([&]() { return KSPSolve(impl->ksp, rhs, solution); }, "KSPSolve");
  ++solves;
  Vector<double> complete(solution);
  impl->homogeneous.distribute(complete);
  return complete;
}

template <int dim>
std::vector<std::vector<double>>
StiffnessFactorization<dim>::responses(const std::vector<SparseLoad>& loads,
                                       const std::vector<types::global_dof_index>& rows) const
{
  // The values at `rows` need, for a constrained row, its masters' values: gather both.
  const std::vector<types::global_dof_index> needed = impl->values_needed(rows);
  auto position = [&](types::global_dof_index dof)
  { return std::lower_bound(needed.begin(), needed.end(), dof) - needed.begin(); };

  std::vector<std::vector<double>> result(loads.size(), std::vector<double>(rows.size(), 0.));
  if (impl->dense &&
      std::includes(impl->interface.begin(), impl->interface.end(), needed.begin(), needed.end()) &&
      impl->interface_responses(loads, rows, result))
  {
    solves += loads.size();
    return result;
  }
  // Loads on few DoFs, values wanted at few DoFs: entries of K⁻¹ rather than whole solutions.
  std::vector<types::global_dof_index> targets;
  for (const auto& load : loads)
    for (const auto& [dof, value] : load)
      for (const auto& [target, weight] : impl->condensed_targets(dof))
        targets.push_back(target);
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  auto target_position = [&](types::global_dof_index dof)
  { return std::lower_bound(targets.begin(), targets.end(), dof) - targets.begin(); };
  const std::vector<double> inverse = impl->inverse_entries(targets, needed);
  solves += loads.size();
  // Each row's value from the needed ones (position in `needed`, weight), found once for all
  // loads.
  std::vector<std::vector<std::pair<unsigned int, double>>> row_terms(rows.size());
  for (unsigned int r = 0; r < rows.size(); ++r)
    for (const auto& [target, weight] : impl->condensed_targets(rows[r]))
      row_terms[r].emplace_back(position(target), weight);
  std::vector<double> at_needed(needed.size());
  for (unsigned int j = 0; j < loads.size(); ++j)
  {
    std::fill(at_needed.begin(), at_needed.end(), 0.);
    for (const auto& [dof, value] : loads[j])
      for (const auto& [target, weight] : impl->condensed_targets(dof))
      {
        const double* column = &inverse[target_position(target) * needed.size()];
        for (unsigned int i = 0; i < needed.size(); ++i)
          at_needed[i] += weight * value * column[i];
      }
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto& [k, weight] : row_terms[r])
        result[j][r] += weight * at_needed[k];
  }
  return result;
}

template <int dim>
std::vector<std::vector<double>>
StiffnessFactorization<dim>::load_responses(const std::vector<SparseLoad>& loads,
                                            const std::vector<types::global_dof_index>& rows,
                                            const std::function<void(std::size_t)>& solved) const
{
  if (Utilities::MPI::n_mpi_processes(impl->mpi_communicator) > 1)
  {
    auto result = responses(loads, rows);
    if (solved)
      solved(loads.size());
    return result;
  }
  // Right-hand sides a block: the dense solutions of a block stay under 2²⁴ values (128 MB).
  // Measured 2026-12-05 (helical built-in pair, 13 layers, 1099 loads a gear of 88k/106k DoFs,
  // one rank): blocks of 128, 256, 512 took 6.5/6.8, 6.7/6.8, 7.0/7.9 s (pinion/wheel), against
  // 18.6/14.3 s for responses(), the same k to every printed digit.
  const std::size_t n = impl->n_dofs;
  const std::size_t block = std::clamp<std::size_t>((std::size_t(1) << 24) / n, 8, 256);
  std::vector<std::vector<std::pair<types::global_dof_index, double>>> row_terms(rows.size());
  for (unsigned int r = 0; r < rows.size(); ++r)
    row_terms[r] = impl->condensed_targets(rows[r]);
  std::vector<std::vector<double>> result(loads.size(), std::vector<double>(rows.size(), 0.));
  for (std::size_t first = 0; first < loads.size(); first += block)
  {
    const std::size_t count = std::min(block, loads.size() - first);
    // The block's loads as the rows of a sparse matrix Bᵀ (condensed onto the free DoFs).
    std::vector<PetscInt> starts{0}, columns;
    std::vector<PetscScalar> values;
    for (std::size_t j = first; j < first + count; ++j)
    {
      std::map<PetscInt, double> row;
      for (const auto& [dof, value] : loads[j])
        for (const auto& [target, weight] : impl->condensed_targets(dof))
          row[static_cast<PetscInt>(target)] += weight * value;
      for (const auto& [column, value] : row)
      {
        columns.push_back(column);
        values.push_back(value);
      }
      starts.push_back(static_cast<PetscInt>(columns.size()));
    }
    OwnedMat loads_transposed, solutions; // destroyed however the block ends
    check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, static_cast<PetscInt>(count),
                                    static_cast<PetscInt>(n), starts.data(), columns.data(),
                                    values.data(), &loads_transposed.mat),
          "MatCreateSeqAIJWithArrays");
    check(MatCreateSeqDense(PETSC_COMM_SELF, static_cast<PetscInt>(n), static_cast<PetscInt>(count),
                            nullptr, &solutions.mat),
          "MatCreateSeqDense");
    impl->call_mumps(
        [&]() { return MatMatTransposeSolve(impl->factor, loads_transposed.mat, solutions.mat); },
        "MatMatTransposeSolve");
    const PetscScalar* solution = nullptr;
    check(MatDenseGetArrayRead(solutions.mat, &solution), "MatDenseGetArrayRead");
    for (std::size_t j = 0; j < count; ++j)
      for (unsigned int r = 0; r < rows.size(); ++r)
        for (const auto& [dof, weight] : row_terms[r])
          result[first + j][r] += weight * solution[j * n + dof];
    check(MatDenseRestoreArrayRead(solutions.mat, &solution), "MatDenseRestoreArrayRead");
    if (solved)
      solved(first + count);
  }
  solves += loads.size();
  return result;
}

template class StiffnessFactorization<2>;
template class StiffnessFactorization<3>;
} // namespace gearstiff::fem
