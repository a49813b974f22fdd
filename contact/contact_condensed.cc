// The Schur-complement path of ContactProblem (contact/contact_problem.h, "Linear algebra"):
// the one factorization, the node columns, the contact system per iteration, hub changes. The
// unit responses a rolling sweep keeps are in contact/contact_columns.cc.
#include "contact/contact_problem_internal.h"
#include "errors/errors.h"

#include <Eigen/Dense>
#include <algorithm>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <iterator>
#include <map>

namespace gearstiff::contact
{
using namespace dealii;

namespace
{
// Whether a rolling position is completed at its reported DoFs from the kept unit responses
// (complete_at_kept_rows) or by one back-substitution of the whole field. 2D: from the kept
// responses (the back-substitution was 0.05–0.15 s of a 0.14 s position, 130k DoFs). 3D: the
// reported rows (fillets and the cells at the supports, ~14k of the 22k rows of the default
// Q1 scene, 457k DoFs) made every unit response cost 15–16 ms instead of 9–10 ms (MUMPS prunes
// the backward solve to the elimination-tree paths of the rows asked for), ~8600 responses per
// rank in a 32-position sweep, against one back-substitution per position.
template <int dim>
constexpr bool completes_from_kept_rows()
{
  return dim == 2;
}
} // namespace

template <int dim>
void ContactProblem<dim>::complete_solution(Vector<double>& residual, bool whole)
{
  if (!condensed || !condensed->partial)
    return;
  if (!whole && complete_at_kept_rows(residual))
    return;
  // u = s·u_p + P (f_friction − Gᵀλ) + R α, one solve with the converged loads.
  Condensed& c = *condensed;
  field_partial = false;
  displacement = c.factorization->response(c.contact_load);
  displacement.add(c.load_factor, c.factorization->particular_solution());
  if (c.particular_change.size() > 0)
    displacement.add(c.load_factor, c.particular_change);
  for (unsigned int j = 0; j < c.amplitudes.size(); ++j)
    displacement.add(c.amplitudes[j], c.factorization->free_modes()[j]);
  residual = elastic.residual(displacement);
  c.partial = false;
  result.right_hand_sides = c.factorization->n_solves();
}

template <int dim>
bool ContactProblem<dim>::complete_at_kept_rows(Vector<double>& residual)
{
  Condensed& c = *condensed;
  if (!completes_from_kept_rows<dim>() || !rolling || !complete_only_at_rows ||
      !c.slave_forces_exact || c.targets.empty())
    return false;
  // The loads f_friction − Gᵀλ act only at contact DoFs, each with its kept unit response, so
  // u = s·(u_p + Δu_p) + Σ_t load_t P e_t + R α at every target, linear in the loads.
  const unsigned int n_dofs = elastic.get_dof_handler().n_dofs();
  std::vector<std::pair<const typename Condensed::KeptResponse*, double>> loaded;
  for (unsigned int i = 0; i < n_dofs; ++i)
    if (c.contact_load[i] != 0.)
    {
      const auto unit = c.unit_columns.find(i);
      if (unit == c.unit_columns.end() || !c.covers_targets(*unit->second.rows))
        return false;
      loaded.emplace_back(&unit->second, c.contact_load[i]);
    }
  std::vector<double> rows(c.targets.size());
  const Vector<double>& particular = c.factorization->particular_solution();
  for (unsigned int k = 0; k < rows.size(); ++k)
  {
    const types::global_dof_index dof = c.targets[k];
    rows[k] = c.load_factor *
              (particular[dof] + (c.particular_change.size() > 0 ? c.particular_change[dof] : 0.));
    for (unsigned int j = 0; j < c.amplitudes.size(); ++j)
      rows[k] += c.amplitudes[j] * c.factorization->free_modes()[j][dof];
  }
  for (const auto& [unit, load] : loaded)
  {
    const std::vector<int>& at = unit->rows->of_target;
    for (unsigned int k = 0; k < rows.size(); ++k)
      rows[k] += load * unit->values[at[k]];
  }
  displacement.reinit(n_dofs);
  for (unsigned int k = 0; k < rows.size(); ++k)
    displacement[c.targets[k]] = rows[k];
  // r = K u − f is exact at the held DoFs (every DoF of their cells is a target); elsewhere
  // it is the contact load (stationarity, as in apply_contact_solution).
  residual = elastic.residual(displacement);
  for (unsigned int i = 0; i < n_dofs; ++i)
    if (!c.held[i])
      residual[i] = c.contact_load[i];
  c.partial = false;
  field_partial = true;
  return true;
}

template <int dim>
void ContactProblem<dim>::complete_only_at(const std::vector<types::global_dof_index>& dofs)
{
  output_dofs = dofs;
  std::sort(output_dofs.begin(), output_dofs.end());
  output_dofs.erase(std::unique(output_dofs.begin(), output_dofs.end()), output_dofs.end());
  complete_only_at_rows = true;
  if (condensed) // the kept responses lack the new rows
  {
    condensed->reported_rows.clear();
    condensed->unit_columns.clear();
    condensed->kept_values = 0;
    condensed->new_rows.reset();
  }
}

template <int dim>
void ContactProblem<dim>::complete_field()
{
  if (!field_partial || !condensed)
    return;
  condensed->partial = true;
  complete_solution(residual_forces, true);
}

template <int dim>
void ContactProblem<dim>::build_condensed(double load_factor)
{
  // Once: supports at unit load factor, hub torques as unit point loads, one factorization.
  const unsigned int n_dofs = elastic.get_dof_handler().n_dofs();
  // Kept only once complete: a failed factorization must not leave a half-built one behind.
  auto built = std::make_unique<Condensed>();
  Condensed& c = *built;
  c.supports = make_support_constraints(1.);
  c.held.assign(n_dofs, false);
  for (const auto& line : c.supports.get_lines())
  {
    c.held[line.index] = true;
    for (const auto& [master, weight] : line.entries)
      c.held[master] = true;
  }
  Vector<double> unit_loads(n_dofs);
  for (const auto& support : supports)
    if (support.hub)
      support.hub->add_loads(unit_loads, 1.);
  if (!rolling)
    collect_contact_dofs(c);
  elastic.set_load_factor(1.);
  // Rolling: the contact DoFs change with every position, so no dense Schur complement on the
  // first position's ones.
  c.factorization = std::make_unique<fem::StiffnessFactorization<dim>>(
      elastic, c.supports, unit_loads, rolling ? std::vector<types::global_dof_index>() : c.dofs);
  // Rᵀ f_tractions = −Rᵀ (K u_p − f) because K R = 0 for rigid modes.
  const Vector<double> unit_residual = elastic.residual(c.factorization->particular_solution());
  elastic.set_load_factor(load_factor);
  map_contact(c);
  for (const auto& mode : c.factorization->free_modes())
    c.mode_loads.push_back(-(mode * unit_residual) + mode * unit_loads);
  result.assembly_time += c.factorization->factorization_time();
  result.factorization_time = c.factorization->factorization_time();
  result.schur_complement = true;
  condensed = std::move(built);
}

template <int dim>
void ContactProblem<dim>::collect_contact_dofs(Condensed& c) const
{
  c.dofs.clear();
  for (const auto& pair : pairs)
    for (const auto& node : pair.nodes)
    {
      for (unsigned int d = 0; d < dim; ++d)
        c.dofs.push_back(node.node.dofs[d]);
      for (const auto& master : node.masters)
        for (unsigned int d = 0; d < dim; ++d)
          c.dofs.push_back(master.node.dofs[d]);
    }
  std::sort(c.dofs.begin(), c.dofs.end());
  c.dofs.erase(std::unique(c.dofs.begin(), c.dofs.end()), c.dofs.end());
}

template <int dim>
void ContactProblem<dim>::map_contact(Condensed& c) const
{
  // What depends on the pairing (the contact DoFs of the current pairs): the nodes'
  // functionals, their column slots, the particular solution and free modes at the DoFs.
  collect_contact_dofs(c);
  c.functionals.clear();
  c.slot.clear();
  c.columns.clear();
  c.modes.clear();
  for (const auto& pair : pairs)
  {
    c.functionals.emplace_back();
    for (const auto& node : pair.nodes)
    {
      std::array<typename Condensed::Functional, dim> functional;
      for (unsigned int d = 0; d < dim; ++d)
        if (!node.rotated)
        {
          functional[d].terms.emplace_back(c.position(node.node.dofs[d]), 1.);
          for (const auto& master : node.masters)
            functional[d].terms.emplace_back(c.position(master.node.dofs[d]), -master.weight);
        }
        else
          for (const auto& [dof, weight] : relative_terms(node, d))
            functional[d].terms.emplace_back(c.position(dof), weight);
      c.functionals.back().push_back(functional);
    }
    c.slot.emplace_back(pair.nodes.size(), -1);
  }
  c.particular = c.at_dofs(c.factorization->particular_solution());
  if (c.particular_change.size() > 0)
    for (unsigned int i = 0; i < c.dofs.size(); ++i)
      c.particular[i] += c.particular_change[c.dofs[i]];
  c.slave_forces_exact = true;
  for (const auto& pair : pairs)
    for (const auto& node : pair.nodes)
      for (unsigned int d = 0; d < dim; ++d)
        c.slave_forces_exact = c.slave_forces_exact && !c.held[node.node.dofs[d]];
  for (const auto& mode : c.factorization->free_modes())
    c.modes.push_back(c.at_dofs(mode));
  c.partial = false;
  c.amplitudes.clear();
  if (rolling)
    map_unit_rows(c);
}

template <int dim>
void ContactProblem<dim>::map_unit_rows(Condensed& c) const
{
  ++c.pairing;
  // complete_only_at(): the reported DoFs and every DoF of the cells at the supports, for
  // their reactions.
  if (completes_from_kept_rows<dim>() && complete_only_at_rows && c.reported_rows.empty())
  {
    c.reported_rows = output_dofs;
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto& cell : elastic.get_dof_handler().active_cell_iterators())
    {
      cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
      cell->get_dof_indices(cell_dofs);
      if (std::any_of(cell_dofs.begin(), cell_dofs.end(),
                      [&](const types::global_dof_index dof) { return c.held[dof]; }))
        c.reported_rows.insert(c.reported_rows.end(), cell_dofs.begin(), cell_dofs.end());
    }
    std::sort(c.reported_rows.begin(), c.reported_rows.end());
    c.reported_rows.erase(std::unique(c.reported_rows.begin(), c.reported_rows.end()),
                          c.reported_rows.end());
  }
  c.targets.clear();
  std::set_union(c.dofs.begin(), c.dofs.end(), c.reported_rows.begin(), c.reported_rows.end(),
                 std::back_inserter(c.targets));
  c.contact_target.resize(c.dofs.size());
  for (unsigned int i = 0; i < c.dofs.size(); ++i)
    c.contact_target[i] =
        std::lower_bound(c.targets.begin(), c.targets.end(), c.dofs[i]) - c.targets.begin();
}

template <int dim>
std::vector<typename ContactProblem<dim>::ContactRow> ContactProblem<dim>::contact_rows() const
{
  // The contact rows G of this iteration as combinations of node columns, with their
  // right-hand sides; a DoF already held (by a support or an earlier row) keeps that hold, as in
  // make_constraints.
  const Condensed& c = *condensed;
  std::vector<ContactRow> rows;
  std::vector<bool> used(elastic.get_dof_handler().n_dofs(), false);
  for (unsigned int p = 0; p < pairs.size(); ++p)
    for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
    {
      if (pairs[p].memory[k].state == NodeState::open)
        continue;
      const SlaveNode<dim>& node = pairs[p].nodes[k];
      const Tensor<1, dim>& n = node.normal;
      if (pairs[p].memory[k].state == NodeState::stick)
      {
        const Tensor<1, dim> start = relative_displacement(node, step_start);
        const Tensor<1, dim> offset = node.initial_gap * n + (start - (start * n) * n);
        for (unsigned int d = 0; d < dim; ++d)
        {
          const types::global_dof_index dof = node.node.dofs[d];
          if (c.supports.is_constrained(dof) || used[dof])
            continue;
          used[dof] = true;
          rows.push_back({{{p, k, d, 1.}}, offset[d]});
        }
      }
      else
      {
        const types::global_dof_index dof = node.node.dofs[normal_component(n)];
        if (used[dof])
          continue;
        used[dof] = true;
        ContactRow row{{}, node.initial_gap};
        for (unsigned int d = 0; d < dim; ++d)
          if (n[d] != 0.)
            row.terms.push_back({p, k, d, n[d]});
        rows.push_back(std::move(row));
      }
    }
  return rows;
}

template <int dim>
std::vector<typename ContactProblem<dim>::ContactTerm> ContactProblem<dim>::friction_terms() const
{
  // Friction loads of the slipping nodes: F_c R_cᵀ, F = μ λ_n along the friction direction.
  std::vector<ContactTerm> terms;
  if (applied_friction() > 0.)
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
        if (pairs[p].memory[k].state == NodeState::slip)
        {
          const Tensor<1, dim> force = std::max(pairs[p].memory[k].friction_bound, 0.) *
                                       pairs[p].memory[k].friction_direction;
          for (unsigned int d = 0; d < dim; ++d)
            if (force[d] != 0.)
              terms.push_back({p, k, d, force[d]});
        }
  return terms;
}

template <int dim>
std::vector<double>
ContactProblem<dim>::Condensed::base_displacement(const std::vector<ContactTerm>& friction_loads,
                                                  double load_factor) const
{
  // u_base = s·u_p + P f_friction at the contact DoFs.
  std::vector<double> base = particular;
  for (double& v : base)
    v *= load_factor;
  for (const ContactTerm& t : friction_loads)
  {
    const std::vector<double>& y = column(t);
    for (unsigned int i = 0; i < base.size(); ++i)
      base[i] += t.coefficient * y[i];
  }
  return base;
}

template <int dim>
Eigen::VectorXd
ContactProblem<dim>::Condensed::free_mode_loads(const std::vector<ContactTerm>& friction_loads,
                                                double load_factor) const
{
  // Rᵀ f of the loads of u_base.
  const unsigned int n_modes = modes.size();
  Eigen::VectorXd mode_load(n_modes);
  for (unsigned int j = 0; j < n_modes; ++j)
  {
    mode_load[j] = load_factor * mode_loads[j];
    for (const ContactTerm& t : friction_loads)
      mode_load[j] += t.coefficient * functional(t)(modes[j]);
  }
  return mode_load;
}

template <int dim>
void ContactProblem<dim>::Condensed::assemble(const std::vector<ContactRow>& rows,
                                              const std::vector<double>& base,
                                              Eigen::MatrixXd& schur, Eigen::MatrixXd& coupling,
                                              Eigen::VectorXd& rhs) const
{
  // S = G P Gᵀ, E = G R, b = G u_base − g.
  const unsigned int m = rows.size(), n_modes = modes.size();
  schur.resize(m, m);
  coupling.resize(m, n_modes);
  rhs.resize(m);
  for (unsigned int i = 0; i < m; ++i)
  {
    for (unsigned int j = 0; j <= i; ++j)
    {
      double value = 0.;
      for (const ContactTerm& a : rows[i].terms)
        for (const ContactTerm& b : rows[j].terms)
          value += a.coefficient * b.coefficient * functional(a)(column(b));
      schur(i, j) = schur(j, i) = value;
    }
    rhs[i] = -rows[i].value;
    for (const ContactTerm& a : rows[i].terms)
      rhs[i] += a.coefficient * functional(a)(base);
    for (unsigned int j = 0; j < n_modes; ++j)
    {
      coupling(i, j) = 0.;
      for (const ContactTerm& a : rows[i].terms)
        coupling(i, j) += a.coefficient * functional(a)(modes[j]);
    }
  }
}

template <int dim>
void ContactProblem<dim>::solve_contact_system(const std::vector<ContactRow>& rows,
                                               const std::vector<ContactTerm>& friction_loads,
                                               double load_factor,
                                               std::vector<double>& multipliers_out,
                                               std::vector<double>& amplitudes_out,
                                               std::vector<double>& base) const
{
  const Condensed& c = *condensed;
  base = c.base_displacement(friction_loads, load_factor);
  const Eigen::VectorXd mode_load = c.free_mode_loads(friction_loads, load_factor);
  const unsigned int m = rows.size(), n_modes = c.modes.size();
  Eigen::MatrixXd schur, coupling;
  Eigen::VectorXd rhs;
  c.assemble(rows, base, schur, coupling, rhs);

  // [S −E; −Eᵀ 0] [λ; α] = [b; −Rᵀf]: λ = S⁻¹(b + Eα), (Eᵀ S⁻¹ E) α = Rᵀf − Eᵀ S⁻¹ b.
  Eigen::VectorXd multipliers = Eigen::VectorXd::Zero(m),
                  amplitudes = Eigen::VectorXd::Zero(n_modes);
  const Eigen::LDLT<Eigen::MatrixXd> schur_factor(schur);
  if (m > 0)
  {
    const Eigen::VectorXd pivots = schur_factor.vectorD().cwiseAbs();
    if (schur_factor.info() != Eigen::Success || pivots.minCoeff() <= 1e-13 * pivots.maxCoeff())
      throw SolverFailure("contact Schur complement",
                          "the closed contact constraints are linearly dependent (a slave node "
                          "constrained twice: do two pairs share a slave surface?)");
  }
  bool restrained = n_modes == 0;
  if (n_modes > 0 && m > 0)
  {
    const Eigen::JacobiSVD<Eigen::MatrixXd> coupling_svd(coupling);
    const Eigen::VectorXd& sigma = coupling_svd.singularValues();
    restrained = sigma.size() == n_modes && sigma.minCoeff() > 1e-10 * sigma.maxCoeff();
  }
  if (!restrained)
  {
    // The closed contacts leave a body free. The reference path's check names the body; it
    // builds the eliminated constraints, which only the reference path needs to be acyclic.
    if (!rolling)
      elastic.check_rigid_body_freedom(make_constraints(load_factor), "linear solve");
    throw SolverFailure("linear solve", "a body held only through contact is free to move: "
                                        "the closed contacts leave a rigid-body motion "
                                        "unrestrained");
  }
  if (n_modes > 0)
  {
    const Eigen::MatrixXd s_inv_e = schur_factor.solve(coupling);
    const Eigen::MatrixXd coarse = coupling.transpose() * s_inv_e;
    amplitudes = coarse.ldlt().solve(mode_load - s_inv_e.transpose() * rhs);
    multipliers = schur_factor.solve(rhs + coupling * amplitudes);
  }
  else if (m > 0)
    multipliers = schur_factor.solve(rhs);
  multipliers_out.assign(multipliers.data(), multipliers.data() + m);
  amplitudes_out.assign(amplitudes.data(), amplitudes.data() + n_modes);
}

template <int dim>
void ContactProblem<dim>::apply_contact_solution(const std::vector<ContactRow>& rows,
                                                 const std::vector<ContactTerm>& friction_loads,
                                                 const std::vector<double>& multipliers,
                                                 const std::vector<double>& amplitudes,
                                                 const std::vector<double>& base,
                                                 double load_factor, Vector<double>& residual)
{
  Condensed& c = *condensed;
  const unsigned int n_dofs = elastic.get_dof_handler().n_dofs();
  // The contact loads f_friction − Gᵀλ (N) at the contact DoFs.
  Vector<double> load(n_dofs);
  auto add_node_load = [&](const ContactTerm& t, double force)
  {
    const SlaveNode<dim>& node = pairs[t.pair].nodes[t.node];
    if (node.rotated)
    {
      for (const auto& [dof, weight] : relative_terms(node, t.component))
        load[dof] += weight * force;
      return;
    }
    load[node.node.dofs[t.component]] += force;
    for (const auto& master : node.masters)
      load[master.node.dofs[t.component]] -= master.weight * force;
  };
  for (const ContactTerm& t : friction_loads)
    add_node_load(t, t.coefficient);
  for (unsigned int i = 0; i < rows.size(); ++i)
    for (const ContactTerm& t : rows[i].terms)
      add_node_load(t, -multipliers[i] * t.coefficient);
  c.contact_load = load;
  c.load_factor = load_factor;
  c.amplitudes = amplitudes;
  c.partial = true;
  if (!c.slave_forces_exact)
  {
    complete_solution(residual);
    return;
  }
  // The states need only the displacements at the contact DoFs, u_C = u_base − Σ λ_i P g_iᵀ +
  // R α, and the forces at the slave DoFs, r = K u − f = f_friction − Gᵀλ there (stationarity
  // of the Lagrangian at a DoF no support touches). The full field waits for convergence.
  std::vector<double> contact_displacement = base;
  for (unsigned int i = 0; i < rows.size(); ++i)
    for (const ContactTerm& t : rows[i].terms)
    {
      const std::vector<double>& y = c.columns[c.slot[t.pair][t.node] + t.component];
      const double factor = -multipliers[i] * t.coefficient;
      for (unsigned int k = 0; k < y.size(); ++k)
        contact_displacement[k] += factor * y[k];
    }
  for (unsigned int j = 0; j < amplitudes.size(); ++j)
    for (unsigned int k = 0; k < c.dofs.size(); ++k)
      contact_displacement[k] += amplitudes[j] * c.modes[j][k];
  displacement.reinit(n_dofs);
  for (unsigned int k = 0; k < c.dofs.size(); ++k)
    displacement[c.dofs[k]] = contact_displacement[k];
  residual = load;
}

template <int dim>
void ContactProblem<dim>::solve_schur_complement(double load_factor, IterationRecord& record,
                                                 Vector<double>& residual)
{
  if (!condensed)
    build_condensed(load_factor); // its assembly and factorization count in assembly_time
  Timer timer(mpi_communicator, true);
  add_new_columns();
  const std::vector<ContactRow> rows = contact_rows();
  const std::vector<ContactTerm> friction_loads = friction_terms();
  std::vector<double> multipliers, amplitudes, base;
  solve_contact_system(rows, friction_loads, load_factor, multipliers, amplitudes, base);
  apply_contact_solution(rows, friction_loads, multipliers, amplitudes, base, load_factor,
                         residual);
  record.n_rows = rows.size();
  record.time = timer.wall_time();
  result.solve_time += record.time;
  result.right_hand_sides = condensed->factorization->n_solves();
}

template <int dim>
void ContactProblem<dim>::add_hub_change(const Support& support, double change)
{
  // The hub at unit target: its point load (torque control) and prescribed displacement
  // (rotation control). Its response is u_c + P (f − K u_c): the supports condensed with
  // homogeneous values, as every other response.
  Condensed& c = *condensed;
  const unsigned int n_dofs = elastic.get_dof_handler().n_dofs();
  const fem::RigidHub<dim> unit(elastic, support.boundary, support.axis, support.control, 1.,
                                support.name);
  Vector<double> loads(n_dofs), prescribed(n_dofs);
  unit.add_loads(loads, 1.);
  AffineConstraints<double> rotation;
  unit.add_constraints(rotation, 1.);
  for (const auto& line : rotation.get_lines())
    if (line.entries.empty())
      prescribed[line.index] = line.inhomogeneity;
  elastic.set_load_factor(0.); // K u_c alone, no tractions
  Vector<double> equivalent = elastic.residual(prescribed);
  elastic.set_load_factor(c.load_factor);
  equivalent.sadd(-1., 1., loads);
  Vector<double> response = c.factorization->response(equivalent);
  response += prescribed;
  if (c.particular_change.size() == 0)
    c.particular_change.reinit(n_dofs);
  c.particular_change.add(change, response);
  const std::vector<double> at_dofs = c.at_dofs(response);
  for (unsigned int i = 0; i < at_dofs.size(); ++i)
    c.particular[i] += change * at_dofs[i];
  // Rᵀ f of the free rigid modes: the torque's work (K R = 0 leaves the prescribed part out).
  for (unsigned int j = 0; j < c.modes.size(); ++j)
    c.mode_loads[j] += change * (c.factorization->free_modes()[j] * loads);
  result.right_hand_sides = c.factorization->n_solves();
}

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
