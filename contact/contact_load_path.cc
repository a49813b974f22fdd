// The load path of ContactProblem: node states, friction bounds, warm and cold starts, the load
// steps with their active-set iterations, and continuation (set_hub_target, solve_next_step).
#include "contact/contact_problem_internal.h"
#include "errors/errors.h"
#include "fem/parallel.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <limits>
#include <string>

namespace gearstiff::contact
{
using namespace dealii;

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
          update_node_state(pair.memory[k], observation, applied_friction(), tolerances);
      changed += update.changed ? 1 : 0;
      if (largest_normal_force > 0.)
        direction_change = std::max(direction_change, update.direction_turn / largest_normal_force);
    }
  return changed;
}

template <int dim>
double ContactProblem<dim>::update_friction_bounds(const Vector<double>& residual)
{
  if (applied_friction() == 0.)
    return 0.;
  double largest_normal_force = 0., largest_change = 0.;
  for (auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const Tensor<1, dim> force = nodal_force(pair.nodes[k], residual); // N, on the slave
      const double normal_force = std::max(-(force * pair.nodes[k].normal), 0.);
      largest_normal_force = std::max(largest_normal_force, normal_force);
      largest_change = std::max(
          largest_change, update_friction_bound(pair.memory[k], normal_force, applied_friction()));
    }
  return largest_normal_force > 0. ? largest_change / largest_normal_force : 0.;
}

template <int dim>
void ContactProblem<dim>::start_friction(const Vector<double>& residual)
{
  friction_in_force = true;
  for (auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
      start_node_friction(pair.memory[k], -(force * node.normal), step_slip(node),
                          applied_friction(), round_off_gap());
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
      solve_refining_load_steps(residual);
    }
  else
    solve_refining_load_steps(residual);
  complete_solution(residual);
  collect_results(residual);
  result.total_time = total.wall_time() + result.setup_time;
  return result;
}

template <int dim>
void ContactProblem<dim>::solve_refining_load_steps(Vector<double>& residual)
{
  // The active set of a frictional contact can cycle on one load step where a finer load path
  // converges: an own pair (z 23/61, m_n 4 mm) with 5.84 µm tip relief cycled at 300 N·m, its
  // stick/slip front at the relief start, and converged in 2 steps (2026-12-02). The same
  // proportional load then goes on in 2 and 4 equal steps from the cold start (friction follows
  // the load path more closely; result.load_steps says how many). A failed factorization would
  // only fail again.
  const unsigned int asked = parameters.load_steps;
  for (unsigned int steps = asked;; steps *= 2)
  {
    parameters.load_steps = steps;
    try
    {
      solve_load_steps(residual);
      parameters.load_steps = asked;
      return;
    }
    catch (const SolverFailure&)
    {
      if (steps >= 4 * asked || (use_schur_complement() && !condensed))
      {
        parameters.load_steps = asked;
        throw;
      }
      restore_cold_start();
    }
  }
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
  friction_in_force = false;
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
      if (friction_in_force || mu == 0. || (use_schur_complement() && !condensed))
        throw;
      friction_in_force = true;
      for (unsigned int p = 0; p < pairs.size(); ++p)
        for (unsigned int k = 0; k < pairs[p].nodes.size(); ++k)
          pairs[p].memory[k].state =
              initial_states[p][k] == NodeState::open ? NodeState::open : NodeState::stick;
      visited.clear();
      continue;
    }
    unsigned int changes = update_states(residual);
    if (changes == 0 && !friction_in_force && mu > 0.)
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
    if (progress)
      progress("load step " + std::to_string(step) + "/" + std::to_string(parameters.load_steps) +
               ", iteration " + std::to_string(iteration) + ": " + std::to_string(record.n_closed) +
               " closed, " + std::to_string(changes) + " changed");
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

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
