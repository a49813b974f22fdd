// The multi-stage planar lateral–torsional model (dynamics/lateral_train.h, issue 30): one stage
// reproduces the one-stage model of lateral_model.h (Lin & Parker 1999, docs/references.md §7,
// §12); the bi-planetary train (docs/references.md §2) tends to the rotational train model with
// stiff bearings and pins, its mode classes follow its cyclic symmetry, its static bearing forces
// balance the mesh and pin forces, and a free translation is refused.
#include "dynamics/lateral_train.h"
#include "dynamics/lateral_train_build.h"
#include "dynamics/lateral_train_response.h"
#include "errors/errors.h"
#include "kinematics/gear_train.h"
#include "lateral_fixtures.h"

#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;
using gearstiff::dynamics::test::lin_parker_example;

namespace
{
// The bi-planetary train (docs/references.md §2, the kinematics' built-in description: modules
// 2/2/2/4 mm) with bench/dynamics_biplanetary.prm's assumed inertias and masses (steel blanks 20 mm
// wide; there 5, 7 and h carry no mass, here their blanks': rings 5 and 7 as 12 mm rims
// ρπb(d_o² − d_i²)/4 = 0.888 and 1.776 kg, carrier h a 320/30 mm disc 12.52 kg, which also
// carries the three rings 5: 15.18 kg — a mass of 5 itself would orbit at a radius the
// kinematics does not know, since 5 meshes only on H); constant mesh
// stiffness 3e8 N/m (illustrative), no damping; ring 7 fixed, or on a torsional spring.
LateralTrainInput biplanetary(double bearing, double pin, double ring_suspension = 0.)
{
  kinematics::GearTrainText text = kinematics::builtin_train("bi-planetary");
  text.inertias = "1: 4.789e-05, 2: 0.009952, 3: 4.789e-05, 4: 8.169e-05, 5: 0.005026, "
                  "6: 0.0007662, 7: 0.04002, h: 0.1614, H: 0.001011";
  text.masses = "1: 0.2088, 2: 2.4271, 3: 0.2088, 4: 0.2727, 6: 0.8353, 7: 1.776, h: 15.18, "
                " H: 0.9988";
  LateralTrainInput input;
  input.train.spec = kinematics::parse_gear_train(text);
  input.train.input_torque = 120.2;
  for (std::size_t m = 0; m < input.train.spec.meshes.size(); ++m)
    input.train.meshes.push_back(
        {MeshStiffness::constant(3e8, "Train mesh/stiffness"), 0., 0., 0., 0., {}, {}, {}, {}});
  if (ring_suspension > 0.)
    input.train.suspensions.push_back({"7", ring_suspension, 0.});
  input.bearing_stiffness = {{"1", bearing}, {"h", bearing}, {"7", bearing}};
  input.pin_stiffness = {{"2", pin}, {"H", pin}, {"4", pin}};
  return input;
}
} // namespace

// One stage through the general form: lateral_train_of_stage gives lateral_model.h's M, K, C and
// pin-error forces to round-off (1e-12 of the largest entry: the general form takes its
// coefficients from the line-of-action angle, cos(ν − β), instead of the stage's sin α, cos α),
// hence its frequencies (1e-9 relative, 1e-6 Hz absolute for the rigid rotation) — which
// reproduce Lin & Parker's printed values (LateralModel.LinParkerExampleFrequencies): N = 3 here
// to the printed digit (0.051 Hz). Also unequal spacing with pin errors.
TEST(LateralTrain, OneStageReproducesStageModel)
{
  const std::vector<double> printed3 = {0.0,    743.2,  743.2,  1102.4, 1102.4, 1475.7,
                                        1896.0, 1896.0, 1930.3, 2276.4, 2276.4, 2658.3,
                                        6986.3, 6986.3, 7462.8, 9647.9, 9647.9, 11775.3};
  for (const unsigned int n : {3u, 4u, 5u, 6u})
  {
    LateralStage stage = lin_parker_example(n);
    if (n == 4)
    {
      stage.planet_angles = {0., 80. * M_PI / 180., M_PI, 1.5 * M_PI};
      stage.pin_error_tangential = {30e-6, 0., -10e-6, 0.};
      stage.pin_error_radial = {0., 20e-6, 0., 0.};
    }
    const LateralModel one(stage);
    const LateralTrainModel general(lateral_train_of_stage(stage));
    ASSERT_EQ(general.n_dofs(), one.n_dofs());
    const double scale = one.stiffness().cwiseAbs().maxCoeff();
    EXPECT_LE((general.stiffness() - one.stiffness()).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LE((general.damping() - one.damping()).cwiseAbs().maxCoeff(),
              1e-12 * one.damping().cwiseAbs().maxCoeff() + 1e-300);
    EXPECT_LE((general.mass() - one.mass()).cwiseAbs().maxCoeff(), 0.);
    EXPECT_LE((general.pin_error_force() - one.pin_error_force()).cwiseAbs().maxCoeff(),
              1e-12 * scale * 1e-4);
    EXPECT_EQ(general.free_dofs(), one.free_dofs());
    const Eigen::VectorXd f1 = one.modes().frequencies, f2 = general.modes().frequencies;
    for (Eigen::Index k = 0; k < f1.size(); ++k)
    {
      EXPECT_NEAR(f2[k], f1[k], 1e-9 * f1[k] + 1e-6) << "N = " << n << ", mode " << k;
      if (n == 3)
      {
        EXPECT_NEAR(f2[k], printed3[k], 0.051) << "mode " << k;
      }
    }
  }
}

// With very stiff bearings and pins the bi-planetary train's lateral model tends to the purely
// rotational train model (train_model.h) of the same train: its 17 lowest frequencies (the
// rigid rotation included; ring 7 fixed: rotations of sun 1, planets 2 ×3, planets 4 ×9,
// carrier h, carriers H ×3) converge to the rotational ones at the rate of the neglected
// compliance (first order in 1/k: the error falls about tenfold from 1e12 to 1e13 N/m, ratio
// checked within 5…20), within 1e-4 relative at 1e13 N/m; the next lateral frequency belongs to
// the bearings and pins, far above (88 kHz against the rotational model's highest 13.8 kHz). The
// rotational model's carrier inertias hold m·R² of the orbiting planets, the nested ones' too (R =
// 102 mm on h, 45 mm on H): in the lateral model that inertia comes from the planets' translations;
// this checks the nested geometry (gear 5 rigid with h around each carrier H's axis, sun 3 on
// planet 2's) and the mesh flanks.
TEST(LateralTrain, BiPlanetaryStiffLimitIsRotationalModel)
{
  for (const double suspension : {0., 1e6})
  {
    const LateralTrainSetup stiff = build_lateral_train(biplanetary(1e13, 1e13, suspension));
    const LateralTrainSetup softer = build_lateral_train(biplanetary(1e12, 1e12, suspension));
    const Eigen::VectorXd rotational =
        TorsionalModel(stiff.rotational.train).mode_shapes().frequencies;
    const Eigen::VectorXd f = LateralTrainModel(stiff.train).modes().frequencies;
    const Eigen::VectorXd g = LateralTrainModel(softer.train).modes().frequencies;
    ASSERT_EQ(rotational.size(), suspension > 0. ? 18 : 17);
    for (Eigen::Index k = 0; k < rotational.size(); ++k)
    {
      const double error = std::abs(f[k] - rotational[k]);
      EXPECT_LE(error, 1e-4 * rotational[k] + 1e-3)
          << "mode " << k << ": " << f[k] << " against " << rotational[k];
      if (rotational[k] > 1.)
      {
        const double ratio = std::abs(g[k] - rotational[k]) / error;
        EXPECT_GT(ratio, 5.) << "mode " << k;
        EXPECT_LT(ratio, 20.) << "mode " << k;
      }
    }
    EXPECT_GT(f[rotational.size()], 5. * rotational[rotational.size() - 1]);
  }
}

// Mode classes of the bi-planetary train with bearings and pins of 1e8 N/m. Derivation (this
// test's oracle): the train has the cyclic symmetry C3 of its three outer positions (each inner
// set placed alike in its own radial frame). Its modes then transform as the group's
// representations k = 0 and k = ±1. The central members' rotations are invariant (k = 0), their
// translations (x, y) transform as k = ±1; so a k = 0 mode has no central translation
// (rotational, simple) and a k = ±1 pair no central rotation (translational, double). There are
// no planet modes (Lin & Parker's N − 3 = 0 for three planets, in both sets: the inner sets'
// "central" members, planet 2, carrier H and gear 5, all move with the outer stage). Counting:
// each orbit of three bodies (planets 2, carriers H, and the three orbits of the planets 4) gives
// 3 coordinates per representation; the central bodies sun 1 and carrier h (and ring 7 when
// suspended) one rotation each to k = 0 and one (x, y) pair to k = ±1 (ring 7 its x, y also when
// fixed): 5·3 + 2 = 17 rotational (18 suspended), the rigid rotation included, and 5·3 + 3 = 18
// translational pairs; 17 + 36 = 53 coordinates (54). Found: exactly that.
TEST(LateralTrain, BiPlanetaryModeClasses)
{
  for (const double suspension : {0., 1e6})
  {
    const LateralTrainSetup setup = build_lateral_train(biplanetary(1e8, 1e8, suspension));
    const LateralTrainModel model(setup.train);
    const LateralTrainModes modes = model.modes();
    ASSERT_EQ(modes.frequencies.size(), suspension > 0. ? 54 : 53);
    unsigned int rotational = 0, translational = 0, other = 0;
    for (const LateralModeGroup& g : modes.groups)
    {
      if (g.type == LateralModeClass::rotational)
      {
        ++rotational;
        EXPECT_EQ(g.modes.size(), 1u) << g.frequency;
      }
      else if (g.type == LateralModeClass::translational)
      {
        ++translational;
        EXPECT_EQ(g.modes.size(), 2u) << g.frequency;
      }
      else
        ++other;
    }
    EXPECT_EQ(rotational, suspension > 0. ? 18u : 17u);
    EXPECT_EQ(translational, 18u);
    EXPECT_EQ(other, 0u);
  }
}

// Statics of the bi-planetary train (T1 = 120.2 N·m, ring 7 fixed). With bearings and pins of
// 1e13 N/m every mesh force tends to the rotational model's (1e-3 relative). With 1e8 N/m the
// symmetric load leaves the central members in place, so the meshes 1-2 and 6-7 keep the
// rotational forces (1e-6) and each inner set's three 3-4 (and 4-5) forces keep their sum (torque
// balance of planet 2 and of carrier H about their own axes), but not their shares: planet 2's
// and carrier H's pins yield under the outer mesh forces (some 20–80 µm at 1e8 N/m), which
// offsets sun 3 and carrier H from ring 5 (rigid with h) like a pin error — the inner sets share
// unequally (measured 1.98 / 0.88 / 0.15 of the mean at 1e8 N/m). The output torque is the
// kinematic T1·i = 6932.70 N·m (docs/references.md §2, 1e-5); the housing's forces on the bodies
// sum to zero, and each central body's bearing force equals minus the mesh and pin forces on it,
// summed from the deflections independently of the solver (1e-9 of the largest mesh force).
// With a pin error on one planet 2 the bearings carry load and the balance still holds.
TEST(LateralTrain, BiPlanetaryStaticBalance)
{
  {
    const LateralTrainSetup stiff = build_lateral_train(biplanetary(1e13, 1e13));
    const LateralTrainStatics s =
        LateralTrainModel(stiff.train)
            .static_state(stiff.input_body, stiff.output_body, stiff.input_torque);
    const StaticState rotational = TorsionalModel(stiff.rotational.train).static_state();
    for (std::size_t i = 0; i < s.mesh_force.size(); ++i)
      EXPECT_NEAR(s.mesh_force[i], rotational.mesh_force[i], 1e-3 * rotational.mesh_force[i]) << i;
  }
  for (const double error : {0., 30e-6})
  {
    LateralTrainSetup setup = build_lateral_train(biplanetary(1e8, 1e8));
    for (LateralBody& b : setup.train.bodies)
      if (b.name == "2#1")
        b.pin_error_tangential = error;
    const LateralTrainModel model(setup.train);
    const LateralTrainStatics s =
        model.static_state(setup.input_body, setup.output_body, setup.input_torque);
    const double largest = *std::max_element(s.mesh_force.begin(), s.mesh_force.end());
    if (error == 0.)
    {
      const StaticState rotational = TorsionalModel(setup.rotational.train).static_state();
      for (const std::size_t i : {0u, 1u, 2u, 21u, 22u, 23u}) // 1-2 and 6-7
        EXPECT_NEAR(s.mesh_force[i], rotational.mesh_force[i], 1e-6 * largest) << i;
      for (std::size_t set = 0; set < 6; ++set) // 3-4 and 4-5, three per carrier H
      {
        const std::size_t first = 3 + 3 * set;
        double sum = 0., expected = 0.;
        for (std::size_t i = first; i < first + 3; ++i)
          sum += s.mesh_force[i], expected += rotational.mesh_force[i];
        EXPECT_NEAR(sum, expected, 1e-9 * expected) << set;
      }
      EXPECT_NEAR(s.mesh_force[3] / rotational.mesh_force[3], 1.978, 0.01);
      EXPECT_NEAR(std::abs(s.output_torque), 6932.70, 1e-5 * 6932.70);
    }
    for (const double f : s.mesh_force)
      EXPECT_GT(f, 0.);
    EXPECT_LE(s.bearing_force.colwise().sum().cwiseAbs().maxCoeff(), 1e-9 * largest);
    // Σ over springs of −F·∂δ/∂(global x, y) of each body.
    Eigen::MatrixXd spring_force = Eigen::MatrixXd::Zero(model.n_bodies(), 2);
    for (const auto& spring : model.springs())
    {
      if (spring.group == 0)
        continue;
      const double force = spring.stiffness * model.deflection(spring, s.displacement.data());
      for (const auto& [i, v] : spring.terms)
      {
        const unsigned int b = i / 3;
        const double beta = setup.train.bodies[b].frame_angle;
        if (i % 3 == 0)
          spring_force.row(b) += -force * v * Eigen::RowVector2d(std::cos(beta), std::sin(beta));
        else if (i % 3 == 1)
          spring_force.row(b) += -force * v * Eigen::RowVector2d(-std::sin(beta), std::cos(beta));
      }
    }
    for (unsigned int b = 0; b < model.n_bodies(); ++b)
    {
      if (setup.train.bodies[b].central)
      {
        EXPECT_LE((s.bearing_force.row(b) + spring_force.row(b)).norm(), 1e-9 * largest)
            << setup.train.bodies[b].name;
      }
    }
    if (error > 0.)
    {
      EXPECT_GT(s.bearing_force.row(0).norm(), 1e-3 * largest); // sun 1 carries the error
    }
  }
}

// Bad input: a free translation (every central body without bearing: the whole train drifts)
// is refused naming Train/bearing stiffness; a planet without pin stiffness names Train/planet pin
// stiffness; a bearing on a planet is refused. A floating sun alone is fine (its meshes hold it).
TEST(LateralTrain, BadInput)
{
  auto error_of = [](const LateralTrainInput& input)
  {
    try
    {
      const LateralTrainModel model(build_lateral_train(input).train);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  LateralTrainInput drifting = biplanetary(0., 1e8);
  EXPECT_NE(error_of(drifting).find("train.bearing_stiffness"), std::string::npos)
      << error_of(drifting);
  LateralTrainInput no_pin = biplanetary(1e8, 1e8);
  no_pin.pin_stiffness.erase("4");
  EXPECT_NE(error_of(no_pin).find("train.planet_pin_stiffness"), std::string::npos);
  LateralTrainInput planet_bearing = biplanetary(1e8, 1e8);
  planet_bearing.bearing_stiffness["2"] = 1e8;
  EXPECT_NE(error_of(planet_bearing).find("train.bearing_stiffness"), std::string::npos);
  LateralTrainInput floating = biplanetary(1e8, 1e8);
  floating.bearing_stiffness.erase("1");
  EXPECT_EQ(error_of(floating), "no error");
}

// Time response (lateral_train_response.h): started from the static deflection under constant
// mesh stiffness the train stays there — K_v = 1 on every Train mesh and no orbit (1e-9 of the
// static state, RK4 keeps an equilibrium to round-off) — at a step below the RK4 limit; a step
// above the limit is refused naming Simulation/time step.
TEST(LateralTrain, ResponseKeepsStatics)
{
  const LateralTrainSetup setup = build_lateral_train(biplanetary(1e8, 1e8, 1e6));
  LateralTrainRun run;
  run.input_speed = 1470. * M_PI / 30.;
  run.time_step = 0.5 * lateral_train_step_limit(setup);
  run.window = 2000 * run.time_step;
  const LateralTrainResponse r = integrate_lateral_train(setup, run);
  for (const double kv : r.summary.kv_max)
    EXPECT_NEAR(kv, 1., 1e-9);
  EXPECT_LE(r.summary.orbit_amplitude.maxCoeff(), 1e-9 * 1e-4);
  run.time_step = 1.05 * r.rk4_step_limit;
  try
  {
    integrate_lateral_train(setup, run);
    ADD_FAILURE() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("simulation.time_step"), std::string::npos);
  }
}
