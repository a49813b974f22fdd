#include "contact/contact_problem.h"

#include "errors/errors.h"
#include "fem/parallel.h"
#include "fem/stiffness_factorization.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <map>
#include <sstream>

namespace gearstiff::contact
{
using namespace dealii;

void ContactParameters::declare_parameters(ParameterHandler& prm)
{
  prm.declare_entry("Friction coefficient", "0", Patterns::Double(0., 2.),
                    "-, Coulomb friction coefficient μ between the surfaces (0: frictionless)");
  prm.declare_entry("Max iterations", "40", Patterns::Integer(1, 1000),
                    "-, active-set iterations per load step; reaching it is a solver failure");
  prm.declare_entry("Load steps", "1", Patterns::Integer(1, 1000),
                    "-, equal load increments (friction is path dependent)");
  prm.declare_entry("Search distance", "1", Patterns::Double(0.),
                    "mm, slave points farther than this from the master surface are never "
                    "paired (small sliding: pairing is frozen in the reference configuration)");
  prm.declare_entry("Overlap tolerance", "1e-3", Patterns::Double(0.),
                    "mm, an initial overlap of the bodies beyond this is an input error");
  prm.declare_entry("Friction tolerance", "1e-8", Patterns::Double(1e-14, 1e-2),
                    "-, convergence of the slip forces relative to the largest normal force");
  prm.declare_entry("Warm start", "true", Patterns::Bool(),
                    "true: in a sweep, each position's active-set iteration starts from the "
                    "contact zone its neighbour converged to (mapped by initial gap, as the "
                    "meshes differ), and from the usual cold start should that fail; false: "
                    "every position starts cold (same results, more iterations)");
  prm.declare_entry("Iteration solves", "auto",
                    Patterns::Selection("auto|Schur complement|full re-solve"),
                    "how each active-set iteration is solved: 'Schur complement' factorizes the "
                    "stiffness once and solves for the contact forces only (needs the direct "
                    "solver); 'full re-solve' re-assembles and re-solves everything (the "
                    "reference); 'auto' takes the Schur complement with the direct solver");
}

void ContactParameters::parse_parameters(ParameterHandler& prm)
{
  friction_coefficient = prm.get_double("Friction coefficient");
  max_iterations = prm.get_integer("Max iterations");
  load_steps = prm.get_integer("Load steps");
  search_distance = prm.get_double("Search distance") * 1e-3;
  overlap_tolerance = prm.get_double("Overlap tolerance") * 1e-3;
  friction_tolerance = prm.get_double("Friction tolerance");
  warm_start = prm.get_bool("Warm start");
  const std::string solves = prm.get("Iteration solves");
  iteration_solves = solves == "Schur complement" ? IterationSolves::schur_complement
                     : solves == "full re-solve"  ? IterationSolves::full_resolve
                                                  : IterationSolves::automatic;
}

namespace
{
// The slave DoF a closed contact constrains: the component of the largest |n_c|, so that
// the constraint's coefficients −n_c/n_main stay bounded by one.
template <int dim>
unsigned int normal_component(const Tensor<1, dim>& normal)
{
  unsigned int main = 0;
  for (unsigned int c = 1; c < dim; ++c)
    if (std::abs(normal[c]) > std::abs(normal[main]))
      main = c;
  return main;
}
} // namespace

template <int dim>
ContactProblem<dim>::ContactProblem(MPI_Comm mpi_communicator,
                                    const fem::ElasticityParameters& elasticity,
                                    const fem::LinearSolverParameters& linear_solver,
                                    const ContactParameters& contact)
    : mpi_communicator(mpi_communicator), parameters(contact),
      elastic(mpi_communicator, elasticity, linear_solver)
{
}

template <int dim>
ContactProblem<dim>::~ContactProblem() = default;

template <int dim>
void ContactProblem<dim>::add_displacement(types::boundary_id boundary, const Tensor<1, dim>& value,
                                           const std::string& name,
                                           const std::vector<bool>& components)
{
  Support support;
  support.name = name;
  support.boundary = boundary;
  support.displacement = value;
  support.components = components;
  supports.push_back(std::move(support));
}

template <int dim>
void ContactProblem<dim>::add_rigid_hub(types::boundary_id boundary, const Point<dim>& axis,
                                        typename fem::RigidHub<dim>::Control control, double value,
                                        const std::string& name)
{
  Support support;
  support.name = name;
  support.boundary = boundary;
  support.is_hub = true;
  support.axis = axis;
  support.control = control;
  support.value = value;
  supports.push_back(std::move(support));
}

template <int dim>
void ContactProblem<dim>::add_contact_pair(const std::vector<types::boundary_id>& slave,
                                           const std::vector<types::boundary_id>& master,
                                           const std::string& name)
{
  Pair pair;
  pair.name = name;
  pair.slave = slave;
  pair.master = master;
  pairs.push_back(std::move(pair));
}

template <int dim>
void ContactProblem<dim>::setup_system()
{
  Timer timer(mpi_communicator, true);
  elastic.setup_system();
  const DoFHandler<dim>& dof_handler = elastic.get_dof_handler();
  {
    const auto& points = elastic.support_points();
    Point<dim> low = points.front(), high = points.front();
    for (const auto& p : points)
      for (unsigned int c = 0; c < dim; ++c)
      {
        low[c] = std::min(low[c], p[c]);
        high[c] = std::max(high[c], p[c]);
      }
    characteristic_length = low.distance(high);
  }

  for (auto& support : supports)
  {
    support.nodes = fem::boundary_nodes(dof_handler, {support.boundary});
    if (support.nodes.empty())
      throw InputError(support.name, "boundary id " + std::to_string(support.boundary) +
                                         " has no faces in the mesh");
    if (support.is_hub)
      support.hub = std::make_unique<fem::RigidHub<dim>>(
          elastic, support.boundary, support.axis, support.control, support.value, support.name);
  }

  // A slave node whose normal DoF is held by a support keeps the support and is not coupled;
  // a component held by a roller stays held in the contact constraints too.
  AffineConstraints<double> held;
  add_support_constraints(held, 1.);
  for (auto& pair : pairs)
  {
    // A surface paired with itself closes onto its own nodes: every node would be constrained
    // to itself (the reference path looped forever resolving that chain).
    for (const auto id : pair.slave)
      if (std::find(pair.master.begin(), pair.master.end(), id) != pair.master.end())
        throw InputError(pair.name, "the slave and master surfaces share boundary id " +
                                        std::to_string(id) +
                                        ": a surface cannot be its own contact partner");
    std::vector<SlaveNode<dim>> coupled = mortar_coupling(
        dof_handler, pair.slave, pair.master, parameters.search_distance, elastic.depth());
    pair.nodes.clear();
    for (auto& node : coupled)
      if (!held.is_constrained(node.node.dofs[normal_component(node.normal)]))
        pair.nodes.push_back(std::move(node));
    if (pair.nodes.empty())
      throw InputError(pair.name, "no contact candidates: no node of the slave surface has "
                                  "the master surface within the search distance (" +
                                      std::to_string(parameters.search_distance * 1e3) + " mm)");
    const auto worst = std::min_element(pair.nodes.begin(), pair.nodes.end(),
                                        [](const auto& a, const auto& b)
                                        { return a.initial_gap < b.initial_gap; });
    if (worst->initial_gap < -parameters.overlap_tolerance)
    {
      std::ostringstream where;
      where << "the bodies overlap by " << -worst->initial_gap * 1e3 << " mm at ("
            << worst->node.position * 1e3 << ") mm, beyond the overlap tolerance of "
            << parameters.overlap_tolerance * 1e3 << " mm";
      throw InputError(pair.name, where.str());
    }
  }
  // The initial active set: the nodes touching in the reference configuration and, when no
  // node touches, those at the smallest gap of all pairs. A body held only through the contact
  // (a torque-driven hub) is then supported from the first solve, and meshed surfaces that do
  // not touch exactly (chords of curved outlines leave gaps of h²/8ρ) need no adjustment of the
  // geometry. A node closed at a positive gap is held at that gap: its force turns tensile if it
  // should not touch, and it opens in the next iteration.
  const double touching = 1e-8 * characteristic_length;
  double smallest_gap = std::numeric_limits<double>::max();
  for (const auto& pair : pairs)
    for (const auto& node : pair.nodes)
      smallest_gap = std::min(smallest_gap, node.initial_gap);
  const double closing_gap = std::max(touching, smallest_gap + touching);
  cold_start.clear();
  for (auto& pair : pairs)
  {
    pair.memory.assign(pair.nodes.size(), NodeMemory<dim>());
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      if (pair.nodes[k].initial_gap <= closing_gap)
        pair.memory[k].state = NodeState::slip;
    cold_start.emplace_back();
    for (const auto& memory : pair.memory)
      cold_start.back().push_back(memory.state);
  }
  warm_started = false;
  displacement.reinit(dof_handler.n_dofs());
  step_start.reinit(dof_handler.n_dofs());
  result = ContactResults<dim>();
  condensed.reset();
  result.n_dofs = dof_handler.n_dofs();
  result.n_mpi_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  result.setup_time = timer.wall_time();
}

template <int dim>
Tensor<1, dim> ContactProblem<dim>::relative_displacement(const SlaveNode<dim>& node,
                                                          const Vector<double>& u) const
{
  Tensor<1, dim> relative;
  for (unsigned int c = 0; c < dim; ++c)
  {
    relative[c] = u[node.node.dofs[c]];
    for (const auto& master : node.masters)
      relative[c] -= master.weight * u[master.node.dofs[c]];
  }
  return relative;
}

template <int dim>
Tensor<1, dim> ContactProblem<dim>::nodal_force(const SlaveNode<dim>& node,
                                                const Vector<double>& residual) const
{
  Tensor<1, dim> force;
  for (unsigned int c = 0; c < dim; ++c)
    force[c] = residual[node.node.dofs[c]];
  return force;
}

template <int dim>
Tensor<1, dim> ContactProblem<dim>::step_slip(const SlaveNode<dim>& node) const
{
  Tensor<1, dim> slip =
      relative_displacement(node, displacement) - relative_displacement(node, step_start);
  slip -= (slip * node.normal) * node.normal;
  return slip;
}

template <int dim>
double ContactProblem<dim>::round_off_gap() const
{
  return 1e-12 * characteristic_length;
}

template <int dim>
void ContactProblem<dim>::add_support_constraints(AffineConstraints<double>& constraints,
                                                  double load_factor) const
{
  for (const auto& support : supports)
    if (support.hub)
      support.hub->add_constraints(constraints, load_factor);
    else
      fem::add_prescribed_displacement(support.nodes, load_factor * support.displacement,
                                       constraints, support.components);
}

template <int dim>
AffineConstraints<double> ContactProblem<dim>::make_support_constraints(double load_factor) const
{
  AffineConstraints<double> constraints;
  add_support_constraints(constraints, load_factor);
  constraints.close();
  return constraints;
}

template <int dim>
AffineConstraints<double> ContactProblem<dim>::make_constraints(double load_factor) const
{
  AffineConstraints<double> constraints;
  add_support_constraints(constraints, load_factor);

  for (const auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      if (pair.memory[k].state == NodeState::open)
        continue;
      const SlaveNode<dim>& node = pair.nodes[k];
      const Tensor<1, dim>& n = node.normal;
      if (pair.memory[k].state == NodeState::stick)
      {
        // u_s − Σ w_m u_m = g n + (tangential offset reached at the start of the step).
        const Tensor<1, dim> start = relative_displacement(node, step_start);
        const Tensor<1, dim> offset = node.initial_gap * n + (start - (start * n) * n);
        for (unsigned int c = 0; c < dim; ++c)
        {
          if (constraints.is_constrained(node.node.dofs[c]))
            continue;
          constraints.add_line(node.node.dofs[c]);
          for (const auto& master : node.masters)
            constraints.add_entry(node.node.dofs[c], master.node.dofs[c], master.weight);
          constraints.set_inhomogeneity(node.node.dofs[c], offset[c]);
        }
      }
      else
      {
        // n·u_s = g + Σ w_m n·u_m, solved for the slave component with the largest |n_c|.
        const unsigned int main = normal_component(n);
        const types::global_dof_index dof = node.node.dofs[main];
        constraints.add_line(dof);
        for (unsigned int c = 0; c < dim; ++c)
        {
          if (c != main && n[c] != 0.)
            constraints.add_entry(dof, node.node.dofs[c], -n[c] / n[main]);
          if (n[c] != 0.)
            for (const auto& master : node.masters)
              constraints.add_entry(dof, master.node.dofs[c], master.weight * n[c] / n[main]);
        }
        constraints.set_inhomogeneity(dof, node.initial_gap / n[main]);
      }
    }
  constraints.close();
  return constraints;
}

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
  AffineConstraints<double> supports;                                // at unit load factor
  std::vector<types::global_dof_index> dofs;                         // contact DoFs, sorted
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
  Vector<double> contact_load; // N
  double load_factor = 1.;
  std::vector<double> amplitudes; // m per unit mode
  bool partial = false;
  // m, complete, at unit load factor: what hub target changes after the factorization added
  // to the particular solution (empty: none).
  Vector<double> particular_change;

  unsigned int position(types::global_dof_index dof) const
  {
    return std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin();
  }
  std::vector<double> at_dofs(const Vector<double>& v) const
  {
    std::vector<double> restricted(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      restricted[i] = v[dofs[i]];
    return restricted;
  }
};

template <int dim>
bool ContactProblem<dim>::use_schur_complement() const
{
  switch (parameters.iteration_solves)
  {
  case IterationSolves::schur_complement:
    return true;
  case IterationSolves::full_resolve:
    return false;
  case IterationSolves::automatic:
    break;
  }
  return elastic.get_linear_solver().method == fem::LinearSolverMethod::direct_mumps;
}

template <int dim>
void ContactProblem<dim>::solve_iteration(double load_factor, IterationRecord& record,
                                          Vector<double>& residual)
{
  if (use_schur_complement())
  {
    solve_schur_complement(load_factor, record, residual);
    return;
  }
  fem::LinearSolveStatistics statistics;
  displacement =
      elastic.solve(make_constraints(load_factor), make_point_loads(load_factor), statistics);
  residual = elastic.residual(displacement);
  result.assembly_time += statistics.assembly_time;
  result.solve_time += statistics.solve_time;
  record.time = statistics.assembly_time + statistics.solve_time;
}

template <int dim>
void ContactProblem<dim>::complete_solution(Vector<double>& residual)
{
  if (!condensed || !condensed->partial)
    return;
  // u = s·u_p + P (f_friction − Gᵀλ) + R α, one solve with the converged loads.
  Condensed& c = *condensed;
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

template <int dim>
void ContactProblem<dim>::build_condensed(double load_factor)
{
  // Once: supports at unit load factor, hub torques as unit point loads, one factorization.
  const unsigned int n_dofs = elastic.get_dof_handler().n_dofs();
  // Kept only once complete: a failed factorization must not leave a half-built one behind.
  auto built = std::make_unique<Condensed>();
  Condensed& c = *built;
  c.supports = make_support_constraints(1.);
  Vector<double> unit_loads(n_dofs);
  for (const auto& support : supports)
    if (support.hub)
      support.hub->add_loads(unit_loads, 1.);
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
  elastic.set_load_factor(1.);
  c.factorization =
      std::make_unique<fem::StiffnessFactorization<dim>>(elastic, c.supports, unit_loads, c.dofs);
  // Rᵀ f_tractions = −Rᵀ (K u_p − f) because K R = 0 for rigid modes.
  const Vector<double> unit_residual = elastic.residual(c.factorization->particular_solution());
  elastic.set_load_factor(load_factor);
  for (const auto& pair : pairs)
  {
    c.functionals.emplace_back();
    for (const auto& node : pair.nodes)
    {
      std::array<typename Condensed::Functional, dim> functional;
      for (unsigned int d = 0; d < dim; ++d)
      {
        functional[d].terms.emplace_back(c.position(node.node.dofs[d]), 1.);
        for (const auto& master : node.masters)
          functional[d].terms.emplace_back(c.position(master.node.dofs[d]), -master.weight);
      }
      c.functionals.back().push_back(functional);
    }
    c.slot.emplace_back(pair.nodes.size(), -1);
  }
  c.particular = c.at_dofs(c.factorization->particular_solution());
  std::vector<bool> held(n_dofs, false);
  for (const auto& line : c.supports.get_lines())
  {
    held[line.index] = true;
    for (const auto& [master, weight] : line.entries)
      held[master] = true;
  }
  for (const auto& pair : pairs)
    for (const auto& node : pair.nodes)
      for (unsigned int d = 0; d < dim; ++d)
        c.slave_forces_exact = c.slave_forces_exact && !held[node.node.dofs[d]];
  for (const auto& mode : c.factorization->free_modes())
  {
    c.modes.push_back(c.at_dofs(mode));
    c.mode_loads.push_back(-(mode * unit_residual) + mode * unit_loads);
  }
  result.assembly_time += c.factorization->factorization_time();
  result.schur_complement = true;
  condensed = std::move(built);
}

template <int dim>
void ContactProblem<dim>::add_new_columns()
{
  // Columns for the nodes closed for the first time, in one block of right-hand sides.
  Condensed& c = *condensed;
  std::vector<fem::SparseLoad> loads;
  std::vector<std::pair<unsigned int, unsigned int>> new_nodes;
  for (unsigned int p = 0; p < pairs.size(); ++p)
    for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
      if (pairs[p].memory[k].state != NodeState::open && c.slot[p][k] < 0)
      {
        new_nodes.emplace_back(p, k);
        const SlaveNode<dim>& node = pairs[p].nodes[k];
        for (unsigned int d = 0; d < dim; ++d)
        {
          fem::SparseLoad load{{node.node.dofs[d], 1.}};
          for (const auto& master : node.masters)
            load.emplace_back(master.node.dofs[d], -master.weight);
          loads.push_back(std::move(load));
        }
      }
  if (loads.empty())
    return;
  std::vector<std::vector<double>> columns = c.factorization->responses(loads, c.dofs);
  for (unsigned int j = 0; j < new_nodes.size(); ++j)
    c.slot[new_nodes[j].first][new_nodes[j].second] = c.columns.size() + j * dim;
  for (auto& column : columns)
    c.columns.push_back(std::move(column));
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
  if (friction > 0.)
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
void ContactProblem<dim>::solve_contact_system(const std::vector<ContactRow>& rows,
                                               const std::vector<ContactTerm>& friction_loads,
                                               double load_factor,
                                               std::vector<double>& multipliers_out,
                                               std::vector<double>& amplitudes_out,
                                               std::vector<double>& base) const
{
  const Condensed& c = *condensed;
  auto column = [&](const ContactTerm& t) -> const std::vector<double>&
  { return c.columns[c.slot[t.pair][t.node] + t.component]; };
  auto functional = [&](const ContactTerm& t) -> const typename Condensed::Functional&
  { return c.functionals[t.pair][t.node][t.component]; };

  // u_base = s·u_p + P f_friction at the contact DoFs; Rᵀ f of the same loads.
  base = c.particular;
  for (double& v : base)
    v *= load_factor;
  for (const ContactTerm& t : friction_loads)
  {
    const std::vector<double>& y = column(t);
    for (unsigned int i = 0; i < base.size(); ++i)
      base[i] += t.coefficient * y[i];
  }
  const unsigned int m = rows.size(), n_modes = c.modes.size();
  Eigen::VectorXd mode_load(n_modes);
  for (unsigned int j = 0; j < n_modes; ++j)
  {
    mode_load[j] = load_factor * c.mode_loads[j];
    for (const ContactTerm& t : friction_loads)
      mode_load[j] += t.coefficient * functional(t)(c.modes[j]);
  }

  // S = G P Gᵀ, E = G R, b = G u_base − g.
  Eigen::MatrixXd schur(m, m), coupling(m, n_modes);
  Eigen::VectorXd rhs(m);
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
        coupling(i, j) += a.coefficient * functional(a)(c.modes[j]);
    }
  }

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
Vector<double> ContactProblem<dim>::make_point_loads(double load_factor) const
{
  Vector<double> loads(elastic.get_dof_handler().n_dofs());
  for (const auto& support : supports)
    if (support.hub)
      support.hub->add_loads(loads, load_factor);
  for (const auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      if (pair.memory[k].state == NodeState::slip && friction > 0.)
      {
        // Coulomb: μ λ_n along the friction direction on the slave, the reaction on the
        // master distributed with the mortar weights.
        const Tensor<1, dim> force =
            std::max(pair.memory[k].friction_bound, 0.) * pair.memory[k].friction_direction;
        const SlaveNode<dim>& node = pair.nodes[k];
        for (unsigned int c = 0; c < dim; ++c)
        {
          loads[node.node.dofs[c]] += force[c];
          for (const auto& master : node.masters)
            loads[master.node.dofs[c]] -= master.weight * force[c];
        }
      }
  return loads;
}

template <int dim>
unsigned int ContactProblem<dim>::update_states(const Vector<double>& residual)
{
  double largest_normal_force = 0.;
  for (const auto& pair : pairs)
    for (const auto& node : pair.nodes)
    {
      const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
      largest_normal_force = std::max(largest_normal_force, -(force * node.normal));
    }
  // Round-off levels: a closed node is tensile, an open one penetrating, only beyond these.
  const StateTolerances tolerances{1e-10 * largest_normal_force, round_off_gap()};
  // Weight of the slip in the tangential trial, c = E/(10 h): of the order of a surface node's
  // tangential stiffness. It steers the iteration path only; with c = E/h the stick/slip
  // front of a Cattaneo–Mindlin contact overshot and cycled.
  const double stiffness = 0.1 * elastic.max_youngs_modulus(); // Pa

  unsigned int changed = 0;
  direction_change = 0.;
  for (auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
      NodeObservation<dim> observation;
      observation.normal_force = -(force * node.normal);
      observation.tangential_force = force + observation.normal_force * node.normal;
      observation.gap = node.initial_gap - relative_displacement(node, displacement) * node.normal;
      observation.slip = step_slip(node);
      observation.area = node.area;
      const double h = dim == 2 ? node.area / elastic.depth() : std::sqrt(node.area);
      observation.trial_stiffness = stiffness / h;
      const NodeUpdate update =
          update_node_state(pair.memory[k], observation, friction, tolerances);
      changed += update.changed ? 1 : 0;
      if (largest_normal_force > 0.)
        direction_change = std::max(direction_change, update.direction_turn / largest_normal_force);
    }
  return changed;
}

template <int dim>
double ContactProblem<dim>::update_friction_bounds(const Vector<double>& residual)
{
  if (friction == 0.)
    return 0.;
  double largest_normal_force = 0., largest_change = 0.;
  for (auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const Tensor<1, dim> force = nodal_force(pair.nodes[k], residual); // N, on the slave
      const double normal_force = std::max(-(force * pair.nodes[k].normal), 0.);
      largest_normal_force = std::max(largest_normal_force, normal_force);
      largest_change =
          std::max(largest_change, update_friction_bound(pair.memory[k], normal_force, friction));
    }
  return largest_normal_force > 0. ? largest_change / largest_normal_force : 0.;
}

template <int dim>
void ContactProblem<dim>::start_friction(const Vector<double>& residual)
{
  friction = parameters.friction_coefficient;
  for (auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
      start_node_friction(pair.memory[k], -(force * node.normal), step_slip(node), friction,
                          round_off_gap());
    }
}

template <int dim>
void ContactProblem<dim>::start_from(const std::vector<ContactZone>& zones)
{
  for (auto& pair : pairs)
  {
    const auto zone = std::find_if(zones.begin(), zones.end(),
                                   [&](const ContactZone& z) { return z.pair == pair.name; });
    if (zone == zones.end())
      continue;
    double smallest_gap = std::numeric_limits<double>::max();
    for (const auto& node : pair.nodes)
      smallest_gap = std::min(smallest_gap, node.initial_gap);
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      pair.memory[k].state = pair.nodes[k].initial_gap - smallest_gap <= zone->gap_range
                                 ? NodeState::slip
                                 : NodeState::open;
  }
  warm_started = true;
}

template <int dim>
std::vector<ContactZone> ContactProblem<dim>::converged_zones() const
{
  std::vector<ContactZone> zones;
  for (const auto& pair : pairs)
  {
    double smallest_gap = std::numeric_limits<double>::max(), range = -1.;
    for (const auto& node : pair.nodes)
      smallest_gap = std::min(smallest_gap, node.initial_gap);
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      if (pair.memory[k].state != NodeState::open)
        range = std::max(range, pair.nodes[k].initial_gap - smallest_gap);
    if (range >= 0.)
      zones.push_back({pair.name, range});
  }
  return zones;
}

template <int dim>
void ContactProblem<dim>::restore_cold_start()
{
  for (unsigned int p = 0; p < pairs.size(); ++p)
    for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
    {
      pairs[p].memory[k] = NodeMemory<dim>();
      pairs[p].memory[k].state = cold_start[p][k];
    }
  displacement = 0.;
  step_start = 0.;
  warm_started = false;
}

template <int dim>
const ContactResults<dim>& ContactProblem<dim>::solve()
{
  Timer total(mpi_communicator, true);
  Vector<double> residual;
  // A warm start that fails (cycling, no convergence, a body left free) is no answer yet: the
  // cold start follows, reusing the factorization and the columns computed so far.
  result.warm_start = warm_started;
  if (warm_started)
    try
    {
      solve_load_steps(residual);
    }
    catch (const SolverFailure&)
    {
      if (use_schur_complement() && !condensed)
        throw; // the factorization failed: a cold start would fail the same way
      result.warm_start = false;
      restore_cold_start();
      solve_load_steps(residual);
    }
  else
    solve_load_steps(residual);
  complete_solution(residual);
  collect_results(residual);
  result.total_time = total.wall_time() + result.setup_time;
  return result;
}

template <int dim>
void ContactProblem<dim>::solve_load_steps(Vector<double>& residual)
{
  result.history.clear();
  result.active_set_iterations = 0;
  result.load_steps = parameters.load_steps;
  // With friction, the first load step starts frictionless: its converged contact zone and slip
  // give the frictional iteration a start close to its answer (at the gears' μ = 0.01 the slip
  // directions and zone hardly change), where starting every closed node in stick made the
  // whole zone swing between stick and slip. A body held only by friction has no frictionless
  // equilibrium; the step then starts again with the closed nodes in stick.
  friction = 0.;
  std::vector<std::vector<NodeState>> initial_states;
  for (const auto& pair : pairs)
  {
    initial_states.emplace_back();
    for (const auto& memory : pair.memory)
      initial_states.back().push_back(memory.state);
  }
  for (unsigned int step = 1; step <= parameters.load_steps; ++step)
  {
    solve_load_step(step, initial_states, residual);
    step_start = displacement;
  }
}

template <int dim>
void ContactProblem<dim>::solve_load_step(unsigned int step,
                                          const std::vector<std::vector<NodeState>>& initial_states,
                                          Vector<double>& residual)
{
  const double mu = parameters.friction_coefficient;
  // Steps after the ramp (solve_next_step) are at full load.
  const double load_factor = std::min(1., static_cast<double>(step) / parameters.load_steps);
  elastic.set_load_factor(load_factor);
  for (auto& pair : pairs)
    for (auto& memory : pair.memory)
      memory.reversals = 0;
  CycleDetector visited;
  unsigned int last_changes = 0;
  for (unsigned int iteration = 1; iteration <= parameters.max_iterations; ++iteration)
  {
    fem::interruption_point(); // another MPI rank of a sweep failed: stop here
    IterationRecord record;
    record.load_step = step;
    record.iteration = iteration;
    try
    {
      solve_iteration(load_factor, record, residual);
    }
    catch (const SolverFailure&)
    {
      // A failed factorization (memory) would only fail again: no restart in stick.
      if (friction > 0. || mu == 0. || (use_schur_complement() && !condensed))
        throw;
      friction = mu;
      for (unsigned int p = 0; p < pairs.size(); ++p)
        for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
          pairs[p].memory[k].state =
              initial_states[p][k] == NodeState::open ? NodeState::open : NodeState::stick;
      visited.clear();
      continue;
    }
    unsigned int changes = update_states(residual);
    if (changes == 0 && friction == 0. && mu > 0.)
    {
      start_friction(residual);
      changes = 1; // a new problem: not converged
      visited.clear();
    }
    // Once the states of the Tresca problem settle, the bounds follow the new λ_n.
    const double friction_change =
        changes == 0 ? std::max(update_friction_bounds(residual), direction_change) : 1.;
    ++result.active_set_iterations;
    record.n_changed = changes;
    record.friction_change = changes == 0 ? friction_change : 0.;
    std::vector<signed char> active_set;
    for (const auto& pair : pairs)
      for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      {
        record.n_closed += pair.memory[k].state != NodeState::open;
        record.n_stick += pair.memory[k].state == NodeState::stick;
        record.n_slip += pair.memory[k].state == NodeState::slip;
        active_set.push_back(state_key(pair.memory[k], pair.nodes[k].tangents[0]));
      }
    result.history.push_back(record);
    last_changes = changes;
    if (changes == 0 && friction_change <= parameters.friction_tolerance)
      return;
    if (changes == 0) // new bounds: a new Tresca problem
      visited.clear();
    else if (visited.visit(active_set) >= 3)
      throw SolverFailure("contact active set",
                          "cycling: the same contact state recurred three times (load step " +
                              std::to_string(step) + ", iteration " + std::to_string(iteration) +
                              ", " + std::to_string(changes) + " nodes changing)");
  }
  throw SolverFailure("contact active set",
                      "no convergence within " + std::to_string(parameters.max_iterations) +
                          " iterations at load step " + std::to_string(step) + " (" +
                          std::to_string(last_changes) + " nodes still changing state)");
}

template <int dim>
void ContactProblem<dim>::set_hub_target(const std::string& name, double value)
{
  const auto support =
      std::find_if(supports.begin(), supports.end(),
                   [&name](const Support& s) { return s.is_hub && s.name == name; });
  if (support == supports.end())
    throw InputError(name, "no rigid hub of this name in the contact problem");
  const double change = value - support->value;
  support->value = value;
  if (!support->hub)
    return; // setup_system() builds the hub with the new target
  support->hub = std::make_unique<fem::RigidHub<dim>>(elastic, support->boundary, support->axis,
                                                      support->control, value, support->name);
  if (condensed && change != 0.)
    add_hub_change(*support, change);
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

template <int dim>
const ContactResults<dim>& ContactProblem<dim>::solve_next_step()
{
  if (result.load_steps == 0)
    throw SolverFailure("contact continuation", "solve() must converge before solve_next_step()");
  Timer total(mpi_communicator, true);
  std::vector<std::vector<NodeState>> states;
  for (const auto& pair : pairs)
  {
    states.emplace_back();
    for (const auto& memory : pair.memory)
      states.back().push_back(memory.state);
  }
  Vector<double> residual;
  const unsigned int step = ++result.load_steps;
  solve_load_step(step, states, residual);
  step_start = displacement;
  complete_solution(residual);
  collect_results(residual);
  result.total_time += total.wall_time();
  return result;
}

template <int dim>
void ContactProblem<dim>::collect_results(const Vector<double>& residual)
{
  residual_forces = residual;
  result.pairs.clear();
  for (const auto& pair : pairs)
  {
    PairResult<dim> out;
    out.name = pair.name;
    // Coordinate along the principal direction of the slave nodes, for profiles.
    Point<dim> centre;
    for (const auto& node : pair.nodes)
      centre += node.node.position / static_cast<double>(pair.nodes.size());
    Eigen::Matrix<double, dim, dim> covariance = Eigen::Matrix<double, dim, dim>::Zero();
    for (const auto& node : pair.nodes)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          covariance(i, j) +=
              (node.node.position[i] - centre[i]) * (node.node.position[j] - centre[j]);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, dim, dim>> eigen(covariance);
    Tensor<1, dim> axis;
    for (unsigned int i = 0; i < dim; ++i)
      axis[i] = eigen.eigenvectors()(i, dim - 1);
    unsigned int largest = 0;
    for (unsigned int i = 1; i < dim; ++i)
      if (std::abs(axis[i]) > std::abs(axis[largest]))
        largest = i;
    if (axis[largest] < 0)
      axis = -axis;

    double low = std::numeric_limits<double>::max(), high = -low;
    Tensor<1, dim> tangential_sum;
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      SurfacePoint<dim> point;
      point.position = node.node.position;
      point.coordinate = (node.node.position - centre) * axis;
      const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
      const double normal_force = -(force * node.normal);
      const Tensor<1, dim> tangential_force = force + normal_force * node.normal;
      point.state = pair.memory[k].state;
      const Tensor<1, dim> relative = relative_displacement(node, displacement);
      point.initial_gap = node.initial_gap;
      point.gap = point.state == NodeState::open ? node.initial_gap - relative * node.normal : 0.;
      point.slip = relative - (relative * node.normal) * node.normal;
      if (point.state != NodeState::open)
      {
        point.pressure = normal_force / node.area;
        point.shear = tangential_force / node.area;
        ++out.n_closed;
        out.n_stick += point.state == NodeState::stick;
        out.n_slip += point.state == NodeState::slip;
        low = std::min(low, point.coordinate);
        high = std::max(high, point.coordinate);
      }
      out.force_on_slave += force;
      out.normal_force += normal_force;
      tangential_sum += tangential_force;
      out.max_pressure = std::max(out.max_pressure, point.pressure);
      out.points.push_back(point);
    }
    out.tangential_force = tangential_sum.norm();
    out.contact_length = out.n_closed > 0 ? high - low : 0.;
    std::sort(out.points.begin(), out.points.end(),
              [](const auto& a, const auto& b) { return a.coordinate < b.coordinate; });
    result.pairs.push_back(out);
  }
  result.supports.clear();
  for (const auto& support : supports)
  {
    SupportResult<dim> out;
    out.name = support.name;
    out.is_hub = support.is_hub;
    out.axis = support.axis;
    const fem::Reaction<dim> reaction = fem::reaction(support.nodes, residual, support.axis);
    out.force = reaction.force;
    out.torque = reaction.torque;
    if (support.hub)
      out.rotation = support.hub->rotation(displacement);
    result.supports.push_back(out);
  }
}

template <int dim>
std::vector<std::string> ContactProblem<dim>::output_results(const std::string& directory,
                                                             const std::string& base) const
{
  std::vector<fem::NodalField> fields{
      {"contact_pressure", {}}, {"contact_gap", {}}, {"contact_slip", {}}, {"contact_state", {}}};
  for (const auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      const types::global_dof_index key = node.node.dofs[0];
      const Tensor<1, dim> relative = relative_displacement(node, displacement);
      const bool closed = pair.memory[k].state != NodeState::open;
      const Tensor<1, dim> force = nodal_force(node, residual_forces); // N, on the slave
      fields[0].values[key] = closed ? -(force * node.normal) / node.area : 0.;
      fields[1].values[key] = closed ? 0. : node.initial_gap - relative * node.normal;
      fields[2].values[key] = (relative - (relative * node.normal) * node.normal).norm();
      fields[3].values[key] = static_cast<double>(pair.memory[k].state);
    }
  return elastic.write_vtu(displacement, fields, directory, base);
}

template <int dim>
const ContactResults<dim>& ContactProblem<dim>::run()
{
  setup_system();
  return solve();
}

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
