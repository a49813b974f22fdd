// The torsional model: statics, nominal forces, mesh phase, stability estimate, bad input.
#include "dynamics/split_path_case.h"
#include "dynamics/torsional_model.h"
#include "errors/errors.h"
#include "tests/dynamics/single_pair_train.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;
using namespace gearstiff::test_support;

TEST(TorsionalModel, StaticDeflectionEqualsTorqueOverStiffnessTimesBaseRadiusSquared)
{
  // docs/references.md §1: k' = T1/(r_b1²·Δφ), so the pinion's rotation relative to a held wheel is
  // Δφ = T1/(k·r_b1²). Here Δφ = φ1 − φ2·r_b2/r_b1 (the rigid rotation removed); the static
  // solve is a 2x2 LU, so the agreement is to round-off (1e-12 relative).
  const double k = 327.2e6, T1 = 49.4, r1 = 24.7e-3, r2 = 67.0e-3;
  const TorsionalModel model(single_pair_train(k, 100.));
  const StaticState state = model.static_state();
  const double relative_rotation = state.angle[0] - state.angle[1] * r2 / r1;
  EXPECT_NEAR(relative_rotation / (T1 / (k * r1 * r1)), 1., 1e-12);
  EXPECT_NEAR(state.rigid_acceleration, 0., 1e-9);
  // The paper's ANSYS single-pair value through the model: with k'_j = 327 222 N/mm and
  // r_b1 = 24.667 mm (docs/references.md §1) the model's static rotation of a train with that
  // pinion must be the published Δφ = 2.481e-4 rad to its printed 4 digits (2e-4 relative).
  dynamics::GearTrain published = single_pair_train(327.222e6, 100.);
  published.meshes[0].driver_base_radius = 24.667e-3;
  published.gears[1].torque = -T1 * r2 / 24.667e-3;
  const StaticState at_published = TorsionalModel(published).static_state();
  EXPECT_NEAR(at_published.angle[0] - at_published.angle[1] * r2 / 24.667e-3, 2.481e-4,
              2.481e-4 * 2e-4);
}

TEST(TorsionalModel, SplitPathNominalForceMatchesPublished)
{
  // docs/references.md §1: F_cn = 0.5·T1/(r1·cos α_t) = 0.5·49.397e3/(26.25·cos 20°) = 1001.27 N.
  // With r_b1 = r1·cos α_t = 24.667 mm and T1 = 49.397 N·m the model's static force per mesh
  // must reproduce it to the printed 0.01 N (plus 0.01 N for the paper's rounding of T1).
  SplitPathCase data = split_path_case();
  data.pinion_base_radius = 26.25e-3 * std::cos(20. * M_PI / 180.);
  data.input_torque = 49.397;
  const TorsionalModel exact(split_path_train(data, MeshStiffness::constant(4e8, "k")));
  EXPECT_NEAR(exact.nominal_force(0), 1001.27, 0.02);
  EXPECT_NEAR(exact.nominal_force(1), 1001.27, 0.02);
  // With the dynamic table's rounded r_b1 = 24.7 mm and T1 = 49.4 N·m: T1/(2·r_b1) = 1000.0 N.
  const TorsionalModel table(
      split_path_train(split_path_case(), MeshStiffness::constant(4e8, "k")));
  EXPECT_NEAR(table.nominal_force(0), 49.4 / (2. * 24.7e-3), 1e-9);
}

TEST(TorsionalModel, SplitPathStaticDeflectionPerMesh)
{
  // Each mesh carries half the input torque: δ = T1/(2·r_b1·k) (1e-12 relative, direct solve).
  const double k = 450e6;
  const SplitPathCase data = split_path_case();
  const TorsionalModel model(split_path_train(data, MeshStiffness::constant(k, "k")));
  const StaticState state = model.static_state(false);
  for (int m = 0; m < 2; ++m)
    EXPECT_NEAR(state.deflection[m] / (data.input_torque / (2. * data.pinion_base_radius * k)), 1.,
                1e-12);
}

TEST(TorsionalModel, MeshPhaseFollowsFromWheelPlacement)
{
  // docs/references.md §1: phase = frac(z1·θ/2π); θ = 180°, z1 = 21 → 0.5 of a mesh period.
  EXPECT_NEAR(mesh_phase_from_placement(21, M_PI), 0.5, 1e-14);
  EXPECT_NEAR(mesh_phase_from_placement(21, 120. * M_PI / 180.), 0.0, 1e-12);
  EXPECT_NEAR(mesh_phase_from_placement(20, 100. * M_PI / 180.), 5.555555555555556 - 5., 1e-12);
}

TEST(TorsionalModel, SplitPathGeometryFromKinematics)
{
  // docs/references.md §1: p_et = 7.380 mm and ε_α = 1.500 (the kinematics module reduces the tips
  // so ε_α is exactly 1.5). The pitch point lies 4.28 mm into the 11.07 mm path of contact for the
  // tips reduced by ~0.2 mm (independent hand calculation, ±0.05 mm for the exact tip radii).
  const SplitPathCase data = split_path_case();
  EXPECT_NEAR(data.base_pitch, 7.380e-3, 0.0005e-3);
  EXPECT_NEAR(data.contact_ratio, 1.5, 1e-9); // input echo: the tips are bisected to give it
  EXPECT_NEAR(data.approach_ratio * data.base_pitch, 4.28e-3, 0.05e-3);
}

TEST(TorsionalModel, Rk4LimitOfAnUndampedPairIsTwoRootTwoOverOmega)
{
  // One vibration mode with ω² = k·(r1²/J1 + r2²/J2); classical RK4 on y' = iωy is stable up to
  // h·ω = 2√2 (the imaginary-axis boundary of its stability region). Bisection to 1e-12.
  const double k = 400e6;
  const TorsionalModel model(single_pair_train(k, 0.));
  const double omega = std::sqrt(k * (24.7e-3 * 24.7e-3 / 1.47e-4 + 67.0e-3 * 67.0e-3 / 7.81e-3));
  EXPECT_NEAR(model.highest_natural_frequency() / omega, 1., 1e-10);
  EXPECT_NEAR(model.rk4_step_limit() * omega / (2. * std::sqrt(2.)), 1., 1e-8);
  ASSERT_EQ(model.modal_properties().natural_frequencies.size(), 1u);
  EXPECT_NEAR(model.modal_properties().natural_frequencies[0] * 2. * M_PI / omega, 1., 1e-10);
}

TEST(TorsionalModel, RejectsBadInput)
{
  GearTrain train = single_pair_train(4e8, 100.);
  train.gears[1].inertia = 0.;
  try
  {
    TorsionalModel model(train);
    FAIL() << "zero inertia accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "gear2.inertia"); // app maps it to "Gear 2/inertia"
  }
  train = single_pair_train(4e8, -1.);
  EXPECT_THROW(TorsionalModel model(train), InputError);
  EXPECT_THROW(single_pair_train(-4e8, 100.), InputError); // negative stiffness, at the source
  train = single_pair_train(4e8, 100.);
  train.meshes.push_back(train.meshes[0]); // a closed loop
  EXPECT_THROW(TorsionalModel model(train), InputError);
  train = single_pair_train(4e8, 100.);
  train.meshes[0].contact_ratio = 0.9;
  EXPECT_THROW(TorsionalModel model(train), InputError);
}
