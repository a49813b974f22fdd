#include "contact/contact_problem.h"

#include "contact/contact_problem_internal.h"
#include "contact/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <sstream>

namespace gearstiff::contact
{
using namespace dealii;

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
  // Every member named, in Support's order: a displacement support holds no hub.
  const auto unused = fem::RigidHub<dim>::Control::rotation;
  supports.push_back(Support{name, boundary, value, components, false, {}, unused, 0., {}, {}});
}

template <int dim>
void ContactProblem<dim>::add_rigid_hub(types::boundary_id boundary, const Point<dim>& axis,
                                        typename fem::RigidHub<dim>::Control control, double value,
                                        const std::string& name)
{
  supports.push_back(
      Support{name, boundary, Tensor<1, dim>(), {}, true, axis, control, value, {}, nullptr});
}

template <int dim>
void ContactProblem<dim>::add_contact_pair(const std::vector<types::boundary_id>& slave,
                                           const std::vector<types::boundary_id>& master,
                                           const std::string& name,
                                           const PairingWindow<dim>& window, bool within_one_body)
{
  pairs.push_back(Pair{name, slave, master, window, within_one_body, {}, {}});
}

template <int dim>
void ContactProblem<dim>::setup_system()
{
  Timer timer(mpi_communicator, true);
  elastic.setup_system();
  characteristic_length = mesh_diameter();
  resolve_supports();
  couple_pairs();
  set_cold_start();
  warm_started = false;
  const DoFHandler<dim>& dof_handler = elastic.get_dof_handler();
  displacement.reinit(dof_handler.n_dofs());
  step_start.reinit(dof_handler.n_dofs());
  result = ContactResults<dim>();
  condensed.reset();
  result.n_dofs = dof_handler.n_dofs();
  result.n_mpi_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  result.setup_time = timer.wall_time();
  if (progress)
  {
    std::size_t slave_nodes = 0;
    for (const auto& pair : pairs)
      slave_nodes += pair.nodes.size();
    progress("set-up done: " + std::to_string(result.n_dofs) + " DoFs, " +
             std::to_string(slave_nodes) + " slave nodes, " + format_number(result.setup_time, 3) +
             " s");
  }
}

template <int dim>
double ContactProblem<dim>::mesh_diameter() const
{
  const auto& points = elastic.support_points();
  Point<dim> low = points.front(), high = points.front();
  for (const auto& p : points)
    for (unsigned int c = 0; c < dim; ++c)
    {
      low[c] = std::min(low[c], p[c]);
      high[c] = std::max(high[c], p[c]);
    }
  return low.distance(high);
}

template <int dim>
void ContactProblem<dim>::resolve_supports()
{
  for (auto& support : supports)
  {
    support.nodes = fem::boundary_nodes(elastic.get_dof_handler(), {support.boundary});
    if (support.nodes.empty())
      throw InputError(support.name, "boundary id " + std::to_string(support.boundary) +
                                         " has no faces in the mesh");
    if (support.is_hub)
      support.hub = std::make_unique<fem::RigidHub<dim>>(
          elastic, support.boundary, support.axis, support.control, support.value, support.name);
  }
}

template <int dim>
void ContactProblem<dim>::couple_pairs()
{
  // A slave node whose normal DoF is held by a support keeps the support and is not coupled;
  // a component held by a roller stays held in the contact constraints too.
  AffineConstraints<double> held;
  add_support_constraints(held, 1.);
  // Rolling: the pairs are coupled on the turned bodies, the mesh put back in place at once.
  const std::vector<Point<dim>> reference =
      rolling ? elastic.triangulation().get_vertices() : std::vector<Point<dim>>();
  if (rolling)
    turn_bodies(reference, true);
  try
  {
    for (auto& pair : pairs)
    {
      // A surface paired with itself closes onto its own nodes: every node would be
      // constrained to itself (the reference path looped forever resolving that chain).
      for (const auto id : pair.slave)
        if (std::find(pair.master.begin(), pair.master.end(), id) != pair.master.end())
          throw InputError(pair.name, "the slave and master surfaces share boundary id " +
                                          std::to_string(id) +
                                          ": a surface cannot be its own contact partner");
      std::vector<SlaveNode<dim>> coupled = mortar_coupling(
          elastic.get_dof_handler(), pair.slave, pair.master, parameters.search_distance,
          elastic.depth(), pair.window, surface_geometry);
      pair.nodes.clear();
      for (auto& node : coupled)
        if (!held.is_constrained(node.node.dofs[normal_component(node.normal)]))
          pair.nodes.push_back(std::move(node));
      check_candidates(pair);
      if (rolling)
        set_node_frames(pair);
    }
  }
  catch (...)
  {
    if (rolling)
      turn_bodies(reference, false);
    throw;
  }
  if (rolling)
    turn_bodies(reference, false);
}

template <int dim>
void ContactProblem<dim>::check_candidates(const Pair& pair) const
{
  if (pair.nodes.empty())
    throw InputError(pair.name, "no contact candidates: no node of the slave surface has "
                                "the master surface within the search distance (" +
                                    std::to_string(parameters.search_distance * 1e3) + " mm)");
  const auto worst =
      std::min_element(pair.nodes.begin(), pair.nodes.end(),
                       [](const auto& a, const auto& b) { return a.initial_gap < b.initial_gap; });
  if (worst->initial_gap < -parameters.overlap_tolerance)
  {
    std::ostringstream where;
    where << overlap_reason << -worst->initial_gap * 1e3 << " mm at (" << worst->node.position * 1e3
          << ") mm, beyond the overlap tolerance of " << parameters.overlap_tolerance * 1e3
          << " mm";
    throw InputError(pair.name, where.str());
  }
}

template <int dim>
bool ContactProblem<dim>::closed_within_windows() const
{
  for (const auto& pair : pairs)
    if (pair.window.radius > 0.)
      for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      {
        const Point<dim>& p = pair.nodes[k].node.position; // on the turned bodies
        if (pair.memory[k].state != NodeState::open &&
            pair.window.distance(p) > 0.5 * pair.window.radius)
          return false;
      }
  return true;
}

template <int dim>
void ContactProblem<dim>::set_cold_start()
{
  // The initial active set: the nodes touching in the reference configuration and, when no
  // node touches, those at the smallest gap of all pairs. A body held only through the contact
  // (a torque-driven hub) is then supported from the first solve, and meshed surfaces that do
  // not touch exactly (chords of curved outlines leave gaps of h²/8ρ) need no adjustment of the
  // geometry. A node closed at a positive gap is held at that gap: its force turns tensile if it
  // should not touch, and it opens in the next iteration.
  // A pair within one body (crack faces) holds no body: its touching nodes do not stand for
  // the first touch between bodies (unless no other pair exists).
  const double touching = 1e-8 * characteristic_length;
  const bool between_bodies = std::any_of(pairs.begin(), pairs.end(),
                                          [](const Pair& pair) { return !pair.within_one_body; });
  double smallest_gap = std::numeric_limits<double>::max();
  for (const auto& pair : pairs)
    if (!between_bodies || !pair.within_one_body)
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
}

template <int dim>
void ContactProblem<dim>::roll(const std::vector<BodyRotation<dim>>& new_rotations)
{
  if (!use_schur_complement())
    throw InputError(field::contact("iteration_solves"),
                     "rolling bodies (one mesh for a whole sweep) needs the Schur complement "
                     "with the direct solver");
  rolling = true;
  rotations = new_rotations;
  if (result.n_dofs == 0)
    return; // before setup_system(): it couples the pairs on the turned bodies
  Timer timer(mpi_communicator, true);
  couple_pairs();
  set_cold_start();
  warm_started = false;
  displacement = 0.;
  step_start = 0.;
  const types::global_dof_index n_dofs = result.n_dofs;
  result = ContactResults<dim>();
  result.n_dofs = n_dofs;
  result.n_mpi_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  if (condensed)
    map_contact(*condensed);
  result.setup_time = timer.wall_time();
}

namespace
{
// The turn by `angle` (rad, counter-clockwise) about the z axis.
template <int dim>
Tensor<2, dim> turn_about_z(double angle)
{
  Tensor<2, dim> turn;
  turn[0][0] = turn[1][1] = std::cos(angle);
  turn[1][0] = std::sin(angle);
  turn[0][1] = -turn[1][0];
  if (dim == 3)
    turn[dim - 1][dim - 1] = 1.;
  return turn;
}
} // namespace

template <int dim>
void ContactProblem<dim>::turn_bodies(const std::vector<Point<dim>>& reference, bool turn)
{
  std::vector<bool> moved(reference.size(), false);
  std::vector<Tensor<2, dim>> matrices; // of `rotations`
  for (const auto& rotation : rotations)
    matrices.push_back(turn_about_z<dim>(rotation.angle));
  for (const auto& cell : elastic.triangulation().active_cell_iterators())
  {
    const auto rotation =
        std::find_if(rotations.begin(), rotations.end(),
                     [&](const BodyRotation<dim>& r) { return r.body == cell->material_id(); });
    const Tensor<2, dim>* matrix =
        rotation != rotations.end() ? &matrices[rotation - rotations.begin()] : nullptr;
    for (const unsigned int v : cell->vertex_indices())
    {
      const unsigned int i = cell->vertex_index(v);
      if (moved[i])
        continue;
      moved[i] = true;
      if (!turn || rotation == rotations.end())
        cell->vertex(v) = reference[i];
      else
        cell->vertex(v) = rotation->axis + *matrix * (reference[i] - rotation->axis);
    }
  }
}

template <int dim>
void ContactProblem<dim>::set_node_frames(Pair& pair) const
{
  // The body of a surface: the material of the cells its faces belong to.
  const auto angle_of = [&](const std::vector<types::boundary_id>& ids)
  {
    for (const auto& cell : elastic.get_dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) != ids.end())
        {
          for (const auto& rotation : rotations)
            if (rotation.body == cell->material_id())
              return rotation.angle;
          return 0.;
        }
    return 0.;
  };
  const Tensor<2, dim> slave = turn_about_z<dim>(angle_of(pair.slave));
  const Tensor<2, dim> master = turn_about_z<dim>(angle_of(pair.master));
  for (auto& node : pair.nodes)
  {
    node.rotated = true;
    node.slave_frame = slave;
    node.master_frame = master;
  }
}

template <int dim>
Tensor<1, dim> ContactProblem<dim>::relative_displacement(const SlaveNode<dim>& node,
                                                          const Vector<double>& u) const
{
  if (node.rotated)
  {
    Tensor<1, dim> slave, master; // in the bodies' own frames
    for (unsigned int d = 0; d < dim; ++d)
    {
      slave[d] = u[node.node.dofs[d]];
      for (const auto& m : node.masters)
        master[d] += m.weight * u[m.node.dofs[d]];
    }
    return node.slave_frame * slave - node.master_frame * master;
  }
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
  // Rolling: the residual holds the components of the slave body's own frame.
  return node.rotated ? node.slave_frame * force : force;
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
Vector<double> ContactProblem<dim>::make_point_loads(double load_factor) const
{
  Vector<double> loads(elastic.get_dof_handler().n_dofs());
  for (const auto& support : supports)
    if (support.hub)
      support.hub->add_loads(loads, load_factor);
  for (const auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
      if (pair.memory[k].state == NodeState::slip && applied_friction() > 0.)
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
const ContactResults<dim>& ContactProblem<dim>::run()
{
  setup_system();
  return solve();
}

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
