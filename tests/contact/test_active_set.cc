// The transitions of the contact state machine (contact/active_set.h), one rule per test, on a
// single 2D node with unit area: the rules are those of Hüeber & Wohlmuth (2005) with the
// friction safeguards described in the header. No FE system is involved.
#include "contact/active_set.h"

#include <gtest/gtest.h>

using namespace dealii;
using namespace gearstiff::contact;

namespace
{
constexpr double mu = 0.3;
const StateTolerances tolerances{1e-9, 1e-12}; // N, m
const Tensor<1, 2> tangent({1., 0.});

// A node with the given normal force (N), tangential force along x (N), gap and slip (m).
NodeObservation<2> observe(double normal_force, double tangential_force, double gap = 0.,
                           double slip = 0.)
{
  NodeObservation<2> observation;
  observation.normal_force = normal_force;
  observation.tangential_force = Tensor<1, 2>({tangential_force, 0.});
  observation.gap = gap;
  observation.slip = Tensor<1, 2>({slip, 0.});
  observation.area = 1.;
  observation.trial_stiffness = 1e9; // Pa/m
  return observation;
}

NodeMemory<2> closed(NodeState state, double bound, double direction = -1.)
{
  NodeMemory<2> node;
  node.state = state;
  node.friction_bound = bound;
  node.friction_direction = Tensor<1, 2>({direction, 0.});
  return node;
}
} // namespace

TEST(ActiveSet, OpenNodeClosesOnlyWhenItPenetrates)
{
  NodeMemory<2> node;
  EXPECT_FALSE(update_node_state(node, observe(0., 0., 1e-6), 0., tolerances).changed);
  EXPECT_EQ(node.state, NodeState::open);
  // Within round-off of touching stays open.
  update_node_state(node, observe(0., 0., -1e-13), 0., tolerances);
  EXPECT_EQ(node.state, NodeState::open);
  // Penetrating: closes; without friction a closed node slips.
  EXPECT_TRUE(update_node_state(node, observe(0., 0., -1e-9), 0., tolerances).changed);
  EXPECT_EQ(node.state, NodeState::slip);
}

TEST(ActiveSet, ClosedNodeOpensUnderTensionAndForgetsItsBound)
{
  NodeMemory<2> node = closed(NodeState::stick, 3.);
  // Compression (and round-off tension) keeps it closed.
  update_node_state(node, observe(-1e-10, 0.), mu, tolerances);
  EXPECT_EQ(node.state, NodeState::stick);
  EXPECT_TRUE(update_node_state(node, observe(-1., 0.), mu, tolerances).changed);
  EXPECT_EQ(node.state, NodeState::open);
  EXPECT_LT(node.friction_bound, 0.);
}

TEST(ActiveSet, NodeClosingWithFrictionTakesItsBoundFromTheTrialPressure)
{
  NodeMemory<2> node;
  // Trial pressure c·|g|·A = 1e9 · 1e-9 · 1 = 1 N: bound μ·1 N; no tangential load: stick.
  update_node_state(node, observe(0., 0., -1e-9), mu, tolerances);
  EXPECT_EQ(node.state, NodeState::stick);
  EXPECT_NEAR(node.friction_bound, mu * 1., 1e-12);
}

TEST(ActiveSet, StickWithinTheConeSlipAlongTheForceOutsideIt)
{
  NodeMemory<2> node = closed(NodeState::stick, mu * 10.);
  update_node_state(node, observe(10., 2.9), mu, tolerances); // |t| < μ λ_n = 3 N
  EXPECT_EQ(node.state, NodeState::stick);
  EXPECT_TRUE(update_node_state(node, observe(10., -3.1), mu, tolerances).changed);
  EXPECT_EQ(node.state, NodeState::slip);
  EXPECT_DOUBLE_EQ(node.friction_direction[0], -1.); // along the stick force
}

TEST(ActiveSet, SlipAlongItsOwnFrictionForceReversesOnceThenSticks)
{
  // The friction force points to −x; the node slid +x (against it): consistent, stays slip.
  NodeMemory<2> node = closed(NodeState::slip, 3.);
  EXPECT_FALSE(update_node_state(node, observe(10., -3., 0., 1e-9), mu, tolerances).changed);
  EXPECT_EQ(node.state, NodeState::slip);
  // It slid −x, along its friction force: Coulomb forbids it. The trial t/A − c·s points +x
  // and leaves the cone: it reverses once.
  EXPECT_TRUE(update_node_state(node, observe(10., -3., 0., -1e-8), mu, tolerances).changed);
  EXPECT_EQ(node.state, NodeState::slip);
  EXPECT_DOUBLE_EQ(node.friction_direction[0], 1.);
  EXPECT_EQ(node.reversals, 1u);
  // Sliding along its (new) friction force again: a second reversal is refused, it sticks.
  update_node_state(node, observe(10., 3., 0., 1e-8), mu, tolerances);
  EXPECT_EQ(node.state, NodeState::stick);
}

TEST(ActiveSet, FrictionStartsAgainstTheFrictionlessSlip)
{
  NodeMemory<2> node = closed(NodeState::slip, -1., 0.);
  start_node_friction(node, 10., Tensor<1, 2>({2e-9, 0.}), mu, 1e-12);
  EXPECT_EQ(node.state, NodeState::slip);
  EXPECT_DOUBLE_EQ(node.friction_direction[0], -1.);
  EXPECT_DOUBLE_EQ(node.friction_bound, 3.);
  NodeMemory<2> still = closed(NodeState::slip, -1., 0.);
  start_node_friction(still, 10., Tensor<1, 2>(), mu, 1e-12);
  EXPECT_EQ(still.state, NodeState::stick);
  NodeMemory<2> open;
  start_node_friction(open, 10., Tensor<1, 2>({2e-9, 0.}), mu, 1e-12);
  EXPECT_EQ(open.state, NodeState::open);
}

TEST(ActiveSet, BoundsFollowTheNormalForceOfTheNewTrescaProblem)
{
  NodeMemory<2> node = closed(NodeState::stick, 3.);
  EXPECT_DOUBLE_EQ(update_friction_bound(node, 12., mu), 0.6);
  EXPECT_DOUBLE_EQ(node.friction_bound, 3.6);
  NodeMemory<2> open;
  EXPECT_DOUBLE_EQ(update_friction_bound(open, 12., mu), 0.);
  EXPECT_LT(open.friction_bound, 0.);
}

TEST(ActiveSet, CycleDetectorCountsVisitsAndKeysTellSlipSensesApart)
{
  const NodeMemory<2> forward = closed(NodeState::slip, 3., 1.),
                      backward = closed(NodeState::slip, 3., -1.);
  EXPECT_NE(state_key(forward, tangent), state_key(backward, tangent));
  CycleDetector detector;
  const std::vector<signed char> a{state_key(forward, tangent)}, b{state_key(backward, tangent)};
  EXPECT_EQ(detector.visit(a), 1u);
  EXPECT_EQ(detector.visit(b), 1u);
  EXPECT_EQ(detector.visit(a), 2u);
  EXPECT_EQ(detector.visit(a), 3u);
  detector.clear();
  EXPECT_EQ(detector.visit(a), 1u);
}
