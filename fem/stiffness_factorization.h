// One factorization of the stiffness matrix, reused for every right-hand side an analysis needs.
//
// A contact analysis changes only a few hundred constraint rows between its active-set
// iterations, while the supports (fixed bores, rigid hubs) stay. So K is condensed once with the
// support constraints and factorized once (MUMPS Cholesky); the contact rows are then handled as
// Lagrange multipliers on the small set of contact unknowns (contact/contact_problem.cc), and
// every solve afterwards is a pair of triangular solves.
//
// A body held only through the contacts (a torque-driven pinion, a floating cylinder) makes the
// support-condensed K singular. Its rigid-body modes R are found from the constraints
// (ElasticSystem::free_rigid_modes), and one DoF per mode is fixed: the inverse of the matrix so
// fixed is a generalized inverse P of the singular one (Farhat & Roux 1991, "A method of finite
// element tearing and interconnecting", IJNME 32:1205), and every solution is
//     u = P (f − Gᵀλ) + R α,   Rᵀ (f − Gᵀλ) = 0,
// with α the rigid-body amplitudes the caller solves for together with the multipliers λ.
//
// Every rank holds the complete vectors; the factorization and the solves are distributed.
#pragma once

#include "fem/elastic_system.h"

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace gearstiff::fem
{
// A load vector with few non-zero entries: (DoF, N) pairs.
using SparseLoad = std::vector<std::pair<dealii::types::global_dof_index, double>>;

template <int dim>
class StiffnessFactorization
{
public:
  // Condenses K with `constraints` (the supports, inhomogeneities at unit load factor), fixes
  // the rigid-body modes they leave free, and factorizes. `point_loads` (N, complete, may be
  // empty) are the unit-load-factor point loads (torques of hubs) added to the tractions.
  // `interface_dofs` (may be empty): the DoFs that responses() will load and read (the contact
  // DoFs). On one rank the factorization then also yields the dense Schur complement of K on
  // them (MUMPS ICNTL(19)), so responses() are dense solves of that small matrix instead of
  // sparse triangular solves; PETSc supports this in serial only.
  // Needs the direct solver: SolverFailure when the factorization fails.
  StiffnessFactorization(const ElasticSystem<dim>& system,
                         const dealii::AffineConstraints<double>& constraints,
                         const dealii::Vector<double>& point_loads,
                         const std::vector<dealii::types::global_dof_index>& interface_dofs = {});
  ~StiffnessFactorization();

  // m, the solution for the loads and prescribed displacements at unit load factor, with the
  // free rigid-body modes held at the fixed DoFs (P f + prescribed part).
  const dealii::Vector<double>& particular_solution() const { return particular; }
  // The rigid-body modes the support constraints leave free (complete vectors, unit size:
  // m per unit amplitude); empty when every body is held.
  const std::vector<dealii::Vector<double>>& free_modes() const { return modes; }
  // m, P b: the displacement caused by the load vector b (N, complete), homogeneous supports.
  dealii::Vector<double> response(const dealii::Vector<double>& load) const;
  // m, P b for several sparse loads, only at the DoFs `rows`: result[j][i] is the response to
  // load j at DoF rows[i]. Solved in blocks of right-hand sides.
  std::vector<std::vector<double>>
  responses(const std::vector<SparseLoad>& loads,
            const std::vector<dealii::types::global_dof_index>& rows) const;
  // The same values, solved for the load vectors themselves: MUMPS' sparse right-hand sides
  // (ICNTL(20), PETSc's MatMatTransposeSolve) in blocks, whole solutions read at `rows`. For
  // loads spread over several DoFs each this beats responses(), which asks K⁻¹ column by column
  // for every DoF a load touches (the influence model's line loads, docs/ltca.md "Cost"); for
  // unit loads on single DoFs (the contact DoFs) responses() is the cheaper one. One rank (MUMPS
  // takes sparse right-hand sides centralized); on several it is responses().
  // `solved` (may be empty) is called after each block with the loads solved so far: the
  // influence model's coefficients are a sweep's longest step (tens of seconds in 3D).
  std::vector<std::vector<double>>
  load_responses(const std::vector<SparseLoad>& loads,
                 const std::vector<dealii::types::global_dof_index>& rows,
                 const std::function<void(std::size_t)>& solved = {}) const;

  double factorization_time() const { return factor_seconds; } // s, wall: assembly + factor
  // Whether responses() use the dense Schur complement on the interface DoFs.
  bool dense_interface() const;
  unsigned int n_solves() const { return solves; } // right-hand sides so far

private:
  void factorize_interface();

  struct Implementation; // PETSc objects, kept out of this header
  std::unique_ptr<Implementation> impl;
  dealii::Vector<double> particular;
  std::vector<dealii::Vector<double>> modes;
  double factor_seconds = 0.;
  mutable unsigned int solves = 0;
};
} // namespace gearstiff::fem
