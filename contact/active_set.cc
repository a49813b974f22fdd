#include "contact/active_set.h"

#include <algorithm>
#include <cmath>

namespace gearstiff::contact
{
using namespace dealii;

template <int dim>
NodeUpdate update_node_state(NodeMemory<dim>& node, const NodeObservation<dim>& observation,
                             double mu, const StateTolerances& tolerances)
{
  const double c = observation.trial_stiffness; // Pa/m
  const NodeState old_state = node.state;
  const bool closed = old_state == NodeState::open ? observation.gap < -tolerances.gap
                                                   : observation.normal_force >= -tolerances.force;
  const double normal_trial = // N
      old_state == NodeState::open ? -c * observation.gap * observation.area
                                   : observation.normal_force;
  NodeState new_state = NodeState::open;
  Tensor<1, dim> direction = node.friction_direction;
  if (closed && mu == 0.)
    new_state = NodeState::slip;
  else if (closed)
  {
    // A node closing for the first time gets its bound from the trial pressure.
    if (node.friction_bound < 0.)
      node.friction_bound = mu * std::max(normal_trial, 0.);
    const double bound = node.friction_bound / observation.area; // Pa
    const Tensor<1, dim> trial =
        observation.tangential_force / observation.area - c * observation.slip; // Pa
    const bool inside = trial.norm() <= bound * (1. + 1e-12);
    if (old_state == NodeState::slip && observation.slip * direction > tolerances.gap)
    {
      // The node slid along the friction force it was given, which Coulomb's law forbids.
      // Either it slides the other way or it sticks; the trial decides with c as the estimate
      // of its tangential stiffness. But the slip of a node is coupled to that of its
      // neighbours and to a torque-driven hub, so c can be far off: a pair whose true state is
      // stick then flips between the two slip directions forever. A node reverses once per
      // load step; after that it sticks, and leaves stick only along its stick force, the
      // direction that is consistent for an uncoupled node.
      if (!inside && node.reversals == 0)
      {
        new_state = NodeState::slip;
        direction = trial / trial.norm();
        ++node.reversals;
      }
      else
        new_state = NodeState::stick;
    }
    else if (inside)
      new_state = NodeState::stick;
    else
    {
      new_state = NodeState::slip;
      direction = trial / trial.norm();
    }
  }
  NodeUpdate update;
  update.changed = new_state != old_state;
  if (new_state == NodeState::slip && mu > 0.)
  {
    // A reversal is a change of state; in 3D the direction also turns within the tangent
    // plane, which converges as a fixed point with the bounds (direction_turn).
    update.changed = update.changed || direction * node.friction_direction < 0.;
    if (old_state == NodeState::slip)
      update.direction_turn = node.friction_bound * (direction - node.friction_direction).norm();
    node.friction_direction = direction;
  }
  // An opened node forgets its bound: closing again, it gets one from its trial pressure, not
  // the stale μ λ_n of its earlier contact (which made a node at the edge of the contact close
  // in stick, pull, open and penetrate in turn).
  if (new_state == NodeState::open)
    node.friction_bound = -1.;
  node.state = new_state;
  return update;
}

template <int dim>
void start_node_friction(NodeMemory<dim>& node, double normal_force, const Tensor<1, dim>& slip,
                         double mu, double gap_tolerance)
{
  if (node.state == NodeState::open)
    return;
  node.friction_bound = mu * std::max(normal_force, 0.);
  if (slip.norm() > gap_tolerance)
  {
    node.state = NodeState::slip;
    node.friction_direction = -slip / slip.norm();
  }
  else
    node.state = NodeState::stick;
}

template <int dim>
double update_friction_bound(NodeMemory<dim>& node, double normal_force, double mu)
{
  const double bound = node.state == NodeState::open ? -1. : mu * std::max(normal_force, 0.);
  const double change = node.state == NodeState::open ? 0. : std::abs(bound - node.friction_bound);
  node.friction_bound = bound;
  return change;
}

template <int dim>
signed char state_key(const NodeMemory<dim>& node, const Tensor<1, dim>& tangent)
{
  const signed char state = static_cast<signed char>(node.state);
  if (dim == 2 && node.state == NodeState::slip)
    return node.friction_direction * tangent > 0 ? 3 : 4;
  return state;
}

template NodeUpdate update_node_state(NodeMemory<2>&, const NodeObservation<2>&, double,
                                      const StateTolerances&);
template NodeUpdate update_node_state(NodeMemory<3>&, const NodeObservation<3>&, double,
                                      const StateTolerances&);
template void start_node_friction(NodeMemory<2>&, double, const Tensor<1, 2>&, double, double);
template void start_node_friction(NodeMemory<3>&, double, const Tensor<1, 3>&, double, double);
template double update_friction_bound(NodeMemory<2>&, double, double);
template double update_friction_bound(NodeMemory<3>&, double, double);
template signed char state_key(const NodeMemory<2>&, const Tensor<1, 2>&);
template signed char state_key(const NodeMemory<3>&, const Tensor<1, 3>&);
} // namespace gearstiff::contact
