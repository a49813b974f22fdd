// The contact state machine of one slave node, apart from any FE system: what the primal–dual
// active set with successive Tresca friction (contact_problem.h gives the method) decides from
// the latest solution's forces, gap and slip at the node. ContactProblem applies it to every
// node; the unit tests drive each transition directly (tests/contact/test_active_set.cc).
//
// The rules, with the Hüeber & Wohlmuth (2005, CMAME 194:3147) trials σ_n = λ_n − c·g·A and
// q = t_τ − c·s against the bound μ λ_n:
//   open → closed when the node penetrates beyond round-off; closed → open when its normal
//     force turns tensile beyond round-off (and it then forgets its friction bound);
//   without friction every closed node slips;
//   with friction a node closing for the first time takes its bound from the trial pressure;
//     stick when |q| is within the bound, slip along q otherwise; a slipping node that slid
//     along its own friction force reverses once per load step and sticks after that.
#pragma once

#include <deal.II/base/tensor.h>
#include <map>
#include <vector>

namespace gearstiff::contact
{
enum class NodeState
{
  open = 0,
  stick = 1,
  slip = 2
};

// What a slave node carries from one active-set iteration to the next.
template <int dim>
struct NodeMemory
{
  NodeState state = NodeState::open;
  dealii::Tensor<1, dim> friction_direction; // unit, of the friction force on the slave (slip)
  double friction_bound = -1.;               // N, μ λ_n of the current Tresca problem; < 0: unset
  unsigned int reversals = 0;                // -, slip reversals in the current load step
};

// What the latest solution says about the node.
template <int dim>
struct NodeObservation
{
  double normal_force = 0.;                // N, compressive > 0
  dealii::Tensor<1, dim> tangential_force; // N, on the slave
  double gap = 0.;                         // m, current normal gap
  dealii::Tensor<1, dim> slip;             // m, tangential slip in the current load step
  double area = 0.;                        // m², the node's share of the surface
  double trial_stiffness = 0.;             // Pa/m, c of the trials (steers the path only)
};

struct StateTolerances
{
  double force = 0.; // N, normal forces below this are round-off
  double gap = 0.;   // m, gaps and slips below this are round-off
};

struct NodeUpdate
{
  bool changed = false;       // the state changed, or a slip direction reversed
  double direction_turn = 0.; // N, bound × |turn of the slip direction| (3D fixed point)
};

// The node's next state (and friction direction/bound) from the observation.
template <int dim>
NodeUpdate update_node_state(NodeMemory<dim>& node, const NodeObservation<dim>& observation,
                             double friction_coefficient, const StateTolerances& tolerances);

// After a converged frictionless start: a closed node slips against its frictionless slip
// (sticks where that vanishes), bounded by μ λ_n.
template <int dim>
void start_node_friction(NodeMemory<dim>& node, double normal_force,
                         const dealii::Tensor<1, dim>& slip, double friction_coefficient,
                         double gap_tolerance);

// The bound of a new Tresca problem, μ λ_n (unset for open nodes); returns its change (N).
template <int dim>
double update_friction_bound(NodeMemory<dim>& node, double normal_force,
                             double friction_coefficient);

// A compact key of the node's state for cycle detection; in 2D a slip's sense along `tangent`
// counts too (a reversal is a different state).
template <int dim>
signed char state_key(const NodeMemory<dim>& node, const dealii::Tensor<1, dim>& tangent);

// Counts how often each active set has been met within one Tresca problem: a set met three
// times means the iteration cycles.
class CycleDetector
{
public:
  void clear() { visits.clear(); }
  // How many times `key` has been met, this time included.
  unsigned int visit(const std::vector<signed char>& key) { return ++visits[key]; }

private:
  std::map<std::vector<signed char>, unsigned int> visits;
};
} // namespace gearstiff::contact
