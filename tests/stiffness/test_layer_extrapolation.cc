// Mesh/layer extrapolation (stiffness/layer_extrapolation.h) on results built by hand whose
// layer error is exactly c·Δz²: L and 2L layers give the limit to round-off (an exact oracle of
// Richardson's formula), what is not extrapolated comes from 2L, the costs add, and results that
// are not one analysis on two meshes, or not yet in the asymptotic range, fail instead of
// returning a number.
#include "errors/errors.h"
#include "stiffness/layer_extrapolation.h"

#include <gtest/gtest.h>

using namespace gearstiff;
using stiffness::GearMeshStiffnessResult;

namespace
{
constexpr double torque = 100.;         // N·m
constexpr double r_b1 = 0.03;           // m
constexpr double rotation_limit = 2e-4; // rad, Δφ at Δz → 0
constexpr double unloaded_error = 1e-6; // m, the kinematic TE (no layer error)
constexpr unsigned int coarse_layers = 13;

// A position solved with layer height ∝ `height` (1: L layers, 1/2: 2L): every extrapolated value
// carries the error c·height², each with its own c; what is local to the mesh is marked by height.
GearMeshStiffnessResult solved(double height, double c = 0.03)
{
  const double e = height * height;
  GearMeshStiffnessResult r;
  r.pinion_roll_angle = 0.35;
  r.reference_position = 0.35 * r_b1;
  r.pinion_torque = torque;
  r.pinion_base_radius = r_b1;
  r.wheel_base_radius = 2. * r_b1;
  r.pinion_rotation = rotation_limit * (1. + c * e);
  r.mesh_stiffness = torque / (r_b1 * r_b1 * r.pinion_rotation);
  r.unloaded_transmission_error = unloaded_error;
  r.transmission_error = r_b1 * r.pinion_rotation + unloaded_error;
  r.wheel_torque = -2. * torque * (1. - 0.01 * e);
  r.torque_ratio = std::abs(r.wheel_torque / torque);
  r.tangential_force = 3000. * (1. + 0.02 * e);
  r.axial_force = -800. * (1. - 0.05 * e);
  r.tilting_moment = 25. * (1. + 0.1 * e);
  for (const int j : {-1, 0, 1})
  {
    stiffness::ToothPairLoad load;
    load.pair = j;
    load.load_share = j == 0 ? 0.6 - 0.1 * e : 0.2 + 0.05 * e;
    load.normal_force = 3100. * load.load_share;
    load.resultant = load.normal_force;
    load.max_pressure = 1e9 * (1. + height); // local: from 2L, never extrapolated
    r.pairs.push_back(load);
  }
  r.max_contact_pressure = 1e9 * (1. + height);
  r.pinion_root_stress = 2e8 * (1. + height);
  r.face_load_factor = 1.2 + height;
  r.n_dofs = static_cast<unsigned int>(1000 / height);
  r.active_set_iterations = 3;
  r.total_time = 10. / height;
  r.solve_time = 4. / height;
  return r;
}
} // namespace

TEST(LayerExtrapolation, RemovesAnErrorInTheLayerHeightSquared)
{
  const GearMeshStiffnessResult coarse = solved(1.), fine = solved(0.5);
  const GearMeshStiffnessResult r = stiffness::extrapolate_layers(coarse, fine, coarse_layers);
  EXPECT_NEAR(r.pinion_rotation / rotation_limit, 1., 1e-14);
  EXPECT_NEAR(r.mesh_stiffness / (torque / (r_b1 * r_b1 * rotation_limit)), 1., 1e-14);
  EXPECT_NEAR(r.transmission_error, r_b1 * rotation_limit + unloaded_error, 1e-18);
  EXPECT_NEAR(r.wheel_torque, -2. * torque, 1e-12);
  EXPECT_NEAR(r.torque_ratio, 2., 1e-14);
  EXPECT_NEAR(r.tangential_force, 3000., 1e-10);
  EXPECT_NEAR(r.axial_force, -800., 1e-10);
  EXPECT_NEAR(r.tilting_moment, 25., 1e-12);
  double shares = 0.;
  for (const auto& load : r.pairs)
  {
    EXPECT_NEAR(load.load_share, load.pair == 0 ? 0.6 : 0.2, 1e-14);
    EXPECT_NEAR(load.normal_force, 3100. * load.load_share, 1e-9);
    EXPECT_EQ(load.max_pressure, 1.5e9); // the 2L solve's
    shares += load.load_share;
  }
  EXPECT_NEAR(shares, 1., 1e-14);
  // Local values and the mesh are the 2L solve's; the costs are both solves'.
  EXPECT_EQ(r.max_contact_pressure, fine.max_contact_pressure);
  EXPECT_EQ(r.pinion_root_stress, fine.pinion_root_stress);
  EXPECT_EQ(r.face_load_factor, fine.face_load_factor);
  EXPECT_EQ(r.n_dofs, fine.n_dofs);
  EXPECT_EQ(r.active_set_iterations, 6u);
  EXPECT_DOUBLE_EQ(r.total_time, 30.);
  EXPECT_DOUBLE_EQ(r.solve_time, 12.);
  EXPECT_EQ(r.extrapolated_layers, coarse_layers);
  EXPECT_EQ(r.stiffness_coarse_layers, coarse.mesh_stiffness);
  EXPECT_EQ(r.stiffness_fine_layers, fine.mesh_stiffness);
}

TEST(LayerExtrapolation, SweepsEveryPositionAndTorque)
{
  stiffness::StiffnessSweepResult coarse, fine;
  for (auto* sweep : {&coarse, &fine})
  {
    const double height = sweep == &coarse ? 1. : 0.5;
    sweep->positions = {solved(height, 0.03), solved(height, -0.02)};
    sweep->by_torque = {sweep->positions, {solved(height, 0.01), solved(height, 0.04)}};
    sweep->wall_time = 20. / height;
    sweep->rank_of_position = {0, 1};
  }
  const stiffness::StiffnessSweepResult r =
      stiffness::extrapolate_layers(coarse, fine, coarse_layers);
  ASSERT_EQ(r.positions.size(), 2u);
  ASSERT_EQ(r.by_torque.size(), 2u);
  for (const auto& torque_positions : r.by_torque)
    for (const auto& position : torque_positions)
      EXPECT_NEAR(position.pinion_rotation / rotation_limit, 1., 1e-14);
  EXPECT_NEAR(r.positions[1].pinion_rotation / rotation_limit, 1., 1e-14);
  EXPECT_DOUBLE_EQ(r.wall_time, 60.);
}

TEST(LayerExtrapolation, RefusesTwoDifferentAnalyses)
{
  GearMeshStiffnessResult other = solved(0.5);
  other.pairs.pop_back();
  EXPECT_THROW(stiffness::extrapolate_layers(solved(1.), other, coarse_layers), SolverFailure);
  other = solved(0.5);
  other.reference_position += 1e-4;
  EXPECT_THROW(stiffness::extrapolate_layers(solved(1.), other, coarse_layers), SolverFailure);
}

// A correction over 5 % (the L solve 20 % from its limit) is outside the range where the error
// falls as Δz²: no number. Just inside, the number is returned.
TEST(LayerExtrapolation, FailsOutsideTheAsymptoticRange)
{
  // Δφ(2L) = Δφ∞·(1 + c/4): the correction is c/4.
  EXPECT_NO_THROW(stiffness::extrapolate_layers(solved(1., 0.19), solved(0.5, 0.19), 13));
  EXPECT_THROW(stiffness::extrapolate_layers(solved(1., 0.21), solved(0.5, 0.21), 13),
               SolverFailure);
  EXPECT_THROW(stiffness::extrapolate_layers(solved(1., -0.21), solved(0.5, -0.21), 13),
               SolverFailure);
}
