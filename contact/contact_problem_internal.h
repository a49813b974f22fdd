// Internal to contact/: what the files of ContactProblem share (contact_problem.cc: set-up and
// the reference path; contact_condensed.cc: the Schur-complement path; contact_load_path.cc: the
// active-set iteration, load steps and continuation; contact_output.cc: results and VTU).
#pragma once

#include "contact/contact_problem.h"
#include "fem/stiffness_factorization.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gearstiff::contact
{
// The slave DoF a closed contact constrains: the component of the largest |n_c|, so that
// the constraint's coefficients −n_c/n_main stay bounded by one.
template <int dim>
unsigned int normal_component(const dealii::Tensor<1, dim>& normal)
{
  unsigned int main = 0;
  for (unsigned int c = 1; c < dim; ++c)
    if (std::abs(normal[c]) > std::abs(normal[main]))
      main = c;
  return main;
}

// The relative displacement (slave − masters) of a rotated node in component c of its normal's
// frame, as (DoF, coefficient) terms on the DoFs in their bodies' frames; zero terms left out.
template <int dim>
std::vector<std::pair<dealii::types::global_dof_index, double>>
relative_terms(const SlaveNode<dim>& node, unsigned int c)
{
  std::vector<std::pair<dealii::types::global_dof_index, double>> terms;
  for (unsigned int d = 0; d < dim; ++d)
    if (node.slave_frame[c][d] != 0.)
      terms.emplace_back(node.node.dofs[d], node.slave_frame[c][d]);
  for (const auto& master : node.masters)
    for (unsigned int d = 0; d < dim; ++d)
      if (node.master_frame[c][d] != 0.)
        terms.emplace_back(master.node.dofs[d], -master.weight * node.master_frame[c][d]);
  return terms;
}

// One term of a contact row or friction load: `coefficient` times the relative displacement
// R_c of a node in component c (a row), or the force F_c on it (a friction load).
template <int dim>
struct ContactProblem<dim>::ContactTerm
{
  unsigned int pair, node, component;
  double coefficient;
};

// One closed-contact constraint row of the Schur complement: Σ terms = value.
template <int dim>
struct ContactProblem<dim>::ContactRow
{
  std::vector<ContactTerm> terms;
  double value; // m
};

// Rolling: the rows a kept unit response holds (ContactProblem::rows_for_new_responses).
template <int dim>
struct ContactProblem<dim>::RowSet
{
  std::vector<dealii::types::global_dof_index> rows; // sorted
  unsigned int built = 0;                            // the pairing that built it
  // Position in `rows` of each of `targets` (−1: not a row), valid for the pairing `mapped`;
  // `complete`: none is −1.
  std::vector<int> of_target;
  unsigned int mapped = 0;
  bool complete = false;
};

// The Schur-complement method's data, built once per solve(): the factorization of the
// support-condensed K, the contact DoFs (slave and master DoFs of every candidate node), and
// for every slave node that has been closed its dim columns P R_cᵀ at the contact DoFs, where
// R_c u = u_s,c − Σ_m w_m u_m,c is the node's relative displacement in component c. Every
// contact row (stick: R_c, slip: n·R) and every friction load (F_c R_cᵀ) is a combination of
// these, so nothing else is ever solved for but one full displacement per iteration.
template <int dim>
struct ContactProblem<dim>::Condensed
{
  // A node's relative-displacement functional at the contact DoFs: R_c v = Σ weight·v[index].
  struct Functional
  {
    std::vector<std::pair<unsigned int, double>> terms; // (position in dofs, weight)
    double operator()(const std::vector<double>& v) const
    {
      double value = 0.;
      for (const auto& [i, w] : terms)
        value += w * v[i];
      return value;
    }
  };

  std::unique_ptr<fem::StiffnessFactorization<dim>> factorization;
  dealii::AffineConstraints<double> supports;                        // at unit load factor
  std::vector<dealii::types::global_dof_index> dofs;                 // contact DoFs, sorted
  std::vector<std::vector<std::array<Functional, dim>>> functionals; // [pair][node][c]
  std::vector<std::vector<int>> slot; // [pair][node] → first of its dim columns, −1: none yet
  std::vector<std::vector<double>> columns; // m/N, P R_cᵀ at dofs
  std::vector<double> particular;           // m, unit-load solution at dofs
  std::vector<std::vector<double>> modes;   // free rigid-body modes at dofs
  std::vector<double> mode_loads;           // N·m (work), Rᵀ f at unit load factor
  // No support constrains a slave DoF or takes one as a master: there the contact forces are
  // exactly f_friction − Gᵀλ, and the iterations need no full displacement field.
  bool slave_forces_exact = true;
  // The latest iteration's loads and rigid amplitudes; `partial`: `displacement` holds only the
  // contact DoFs until complete_solution().
  dealii::Vector<double> contact_load; // N
  double load_factor = 1.;
  std::vector<double> amplitudes; // m per unit mode
  bool partial = false;
  // m, complete, at unit load factor: what hub target changes after the factorization added
  // to the particular solution (empty: none).
  dealii::Vector<double> particular_change;
  // Rolling: K and its factorization stay while the pairing changes, so the response P e_t to a
  // unit load at DoF t is kept for every position, at the rows of the row set it was computed
  // with (ContactProblem::rows_for_new_responses). A node's column is then a weighted sum of
  // these; a kept response whose rows miss a target of the current pairing is computed afresh.
  struct KeptResponse
  {
    std::vector<double> values; // m/N, at rows->rows
    std::shared_ptr<RowSet> rows;
    // The pairing (counted by map_unit_rows) that last used it: past the memory bound, those
    // unused the longest are dropped first (ContactProblem::make_room_for_columns).
    unsigned int last_use = 0;
  };
  std::unordered_map<dealii::types::global_dof_index, KeptResponse> unit_columns;
  std::size_t kept_values = 0;      // Σ values.size() over unit_columns
  std::shared_ptr<RowSet> new_rows; // the rows of the latest responses computed
  // What a rolling position needs of every response it uses (sorted): the contact DoFs and,
  // with ContactProblem::complete_only_at, the reported DoFs and every DoF of the cells at the
  // supports (`reported_rows`), where complete_at_kept_rows completes the solution.
  std::vector<dealii::types::global_dof_index> targets, reported_rows;
  std::vector<unsigned int> contact_target; // position in targets of each contact DoF
  // The DoFs of the surfaces the sweep pairs (keep_columns_on and the current pairs' surfaces),
  // sorted, and those surfaces' ids.
  std::vector<dealii::types::global_dof_index> surface_rows;
  std::vector<dealii::types::boundary_id> surface_ids;
  unsigned int pairing = 0;
  // Whether `rows` holds every target (of_target mapped for the current pairing).
  bool covers_targets(RowSet& rows) const
  {
    if (rows.mapped != pairing)
    {
      rows.of_target.resize(targets.size());
      rows.complete = true;
      for (unsigned int k = 0; k < targets.size(); ++k)
      {
        const auto found = std::lower_bound(rows.rows.begin(), rows.rows.end(), targets[k]);
        rows.of_target[k] = found != rows.rows.end() && *found == targets[k]
                                ? static_cast<int>(found - rows.rows.begin())
                                : -1;
        rows.complete = rows.complete && rows.of_target[k] >= 0;
      }
      rows.mapped = pairing;
    }
    return rows.complete;
  }
  // The DoFs a support constrains or takes as a master (their residual is a reaction).
  std::vector<bool> held;

  unsigned int position(dealii::types::global_dof_index dof) const
  {
    return std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin();
  }
  std::vector<double> at_dofs(const dealii::Vector<double>& v) const
  {
    std::vector<double> restricted(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      restricted[i] = v[dofs[i]];
    return restricted;
  }
  const std::vector<double>& column(const ContactTerm& t) const
  {
    return columns[slot[t.pair][t.node] + t.component];
  }
  const Functional& functional(const ContactTerm& t) const
  {
    return functionals[t.pair][t.node][t.component];
  }
  // The steps of solve_contact_system (contact_condensed.cc): u_base (m) at the contact DoFs,
  // Rᵀ f of its loads (N·m), and S, E and b of the contact rows.
  std::vector<double> base_displacement(const std::vector<ContactTerm>& friction_loads,
                                        double load_factor) const;
  Eigen::VectorXd free_mode_loads(const std::vector<ContactTerm>& friction_loads,
                                  double load_factor) const;
  void assemble(const std::vector<ContactRow>& rows, const std::vector<double>& base,
                Eigen::MatrixXd& schur, Eigen::MatrixXd& coupling, Eigen::VectorXd& rhs) const;
};

} // namespace gearstiff::contact
