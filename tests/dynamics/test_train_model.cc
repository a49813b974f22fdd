// The purely rotational model of any train (dynamics/train_model.h) against exact oracles:
// the modal structure of Lin & Parker (1999) for equally spaced identical planets, kinematics'
// reduced inertia J* (gear_train.h) for the rigid mode, kinematics' torque-method statics for the
// mesh forces, energy conservation without damping and friction, and bad input.
#include "dynamics/integrators.h"
#include "dynamics/iso6336_dynamic_factor.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "kinematics/gear_pair.h"
#include "tests/kinematics/shifted_pair.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <tuple>

using namespace gearstiff;
using namespace gearstiff::dynamics;

namespace
{
// The train `text` with `input_torque` (N·m) on its first input and every Train mesh at the
// constant `stiffness` (N/m) with `damping` (N·s/m), without friction.
TrainDynamicsInput constant_mesh_input(const kinematics::GearTrainText& text, double input_torque,
                                       double stiffness, double damping)
{
  TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(text);
  input.input_torque = input_torque;
  for (std::size_t m = 0; m < input.spec.meshes.size(); ++m)
    input.meshes.push_back({MeshStiffness::constant(stiffness, "Train mesh/stiffness"),
                            damping,
                            0.,
                            0.,
                            0.,
                            {},
                            {},
                            {},
                            {}});
  return input;
}

// A single stage: sun s (20 teeth) input, N planets p (10 teeth) on carrier c, ring r (−40)
// fixed, module 2 mm; inertias and planet masses are round illustrative values.
TrainDynamicsInput planetary(unsigned int planets, double stiffness = 4e8, double damping = 0.)
{
  kinematics::GearTrainText text = kinematics::builtin_train("planetary");
  text.planets = "p: c*" + std::to_string(planets);
  text.inertias = "s: 2e-4, p: 5e-5, c: 4e-3, r: 1e-2";
  text.masses = "p: 0.4";
  return constant_mesh_input(text, 100., stiffness, damping);
}

TrainDynamicsInput bi_planetary()
{
  kinematics::GearTrainText text = kinematics::builtin_train("bi-planetary");
  text.inertias = "1: 1e-4, 2: 2e-2, 3: 1e-4, 4: 3e-4, 5: 5e-3, 6: 1e-3, 7: 4e-2, h: 0.5, H: 2e-3";
  // No mass for ring 5: kinematics knows no orbit radius for it (rigid with h, not a planet).
  text.masses = "2: 3.2, 3: 0.3, 4: 0.4, 6: 0.5, H: 0.6";
  return constant_mesh_input(text, 120.2, 5e8, 0.);
}

std::vector<unsigned int> dofs_of(const TrainModel& model, const std::string& body)
{
  std::vector<unsigned int> dofs;
  for (unsigned int i = 0; i < model.dof_body.size(); ++i)
    if (model.dof_body[i] == body)
      dofs.push_back(i);
  return dofs;
}
} // namespace

// Lin & Parker 1999: with N equally spaced identical planets the purely rotational model has
// planet modes of multiplicity N − 1 in which only the planets move. The ring is suspended here
// so that "the ring does not move" is tested too. Tolerance 1e-8 relative (the bound;
// a symmetric eigensolver resolves a repeated eigenvalue to ~1e-14).
TEST(TrainModel, LinParkerPlanetModes)
{
  for (const unsigned int n : {3u, 4u, 5u})
  {
    TrainDynamicsInput input = planetary(n);
    input.suspensions = {{"r", 2e6, 0.}};
    const TrainModel model = build_train_model(input);
    const TorsionalModel torsional(model.train);
    ASSERT_EQ(torsional.n_dofs(), 3 + n);
    const ModeShapes modes = torsional.mode_shapes();
    std::vector<unsigned int> central = dofs_of(model, "s");
    for (const char* name : {"c", "r"})
      central.push_back(dofs_of(model, name).front());
    // The planet-mode frequency: the one shared by N − 1 modes.
    unsigned int found = 0;
    for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k)
    {
      unsigned int same = 0;
      for (Eigen::Index l = 0; l < modes.frequencies.size(); ++l)
        same +=
            std::abs(modes.frequencies[l] - modes.frequencies[k]) <= 1e-8 * modes.frequencies[k];
      if (same != n - 1 || modes.frequencies[k] == 0.)
        continue;
      ++found;
      const double largest = modes.shapes.col(k).cwiseAbs().maxCoeff();
      for (const unsigned int dof : central)
        EXPECT_LE(std::abs(modes.shapes(dof, k)), 1e-8 * largest) << "N = " << n;
    }
    EXPECT_EQ(found, n - 1) << "N = " << n;
  }
}

// The rigid mode (the nominal rotation per unit input speed) carries the kinetic energy
// ½·J*·ω² with kinematics' reduced inertia J* of the same train: the same sum over the same
// bodies, so equal to round-off (1e-12 relative). Nested carriers included (bi-planetary).
TEST(TrainModel, RigidModeEnergyIsReducedInertia)
{
  for (const TrainDynamicsInput& input : {planetary(3), planetary(4), bi_planetary()})
  {
    const TrainModel model = build_train_model(input);
    const TorsionalModel torsional(model.train);
    const Eigen::VectorXd& r = torsional.rigid_mode();
    const double energy = r.cwiseProduct(torsional.inertias()).dot(r);
    EXPECT_NEAR(energy, model.reduced_inertia, 1e-12 * model.reduced_inertia);
  }
}

// Static mesh forces: the same in every copy of a mesh (equally spaced identical planets share
// the load equally) and equal to kinematics' loss-free torque-method force T/(copies·|r_b|)
// (gear_train.h). The model's forces come from the stiffness solution, kinematics' from the
// torque balance: two independent routes, agreement to 1e-9 relative (round-off of the solve).
TEST(TrainModel, StaticForcesEqualKinematicsStatics)
{
  for (const TrainDynamicsInput& input : {planetary(3), planetary(5), bi_planetary()})
  {
    const TrainModel model = build_train_model(input);
    const TorsionalModel torsional(model.train);
    const kinematics::TrainSolution solution = kinematics::solve_train_kinematics(input.spec);
    const kinematics::TrainStatics statics =
        kinematics::solve_train_statics(input.spec, solution, input.input_torque, 0.);
    for (unsigned int i = 0; i < torsional.n_meshes(); ++i)
    {
      const unsigned int m = model.spec_mesh[i];
      const auto& gear = input.spec.members[solution.index(input.spec.meshes[m].gear_a)];
      const double base_radius = 0.5 * gear.module * std::abs(gear.teeth) * std::cos(M_PI / 9.);
      const double expected =
          std::abs(statics.meshes[m].on_a) / (solution.mesh_copies[m] * base_radius);
      EXPECT_GT(torsional.nominal_force(i), 0.);
      EXPECT_NEAR(torsional.nominal_force(i), expected, 1e-9 * expected)
          << model.train.meshes[i].name;
    }
  }
}

// Without damping and friction and with constant stiffness the total energy minus the work of
// the constant torques is conserved. RK4 at 1/200 of the highest period loses
// ≈ (ωh)⁶/144 ≈ 7e-12 of a mode's energy per step, ~3e-8 over 4000 steps; bound 1e-6.
TEST(TrainModel, EnergyBalanceWithoutDamping)
{
  TrainDynamicsInput input = bi_planetary();
  input.suspensions = {{"7", 5e6, 0.}};
  const TrainModel model = build_train_model(input);
  const TorsionalModel torsional(model.train);
  IntegratorSettings settings;
  settings.time_step = 2. * M_PI / torsional.highest_natural_frequency() / 200.;
  settings.end_time = 4000. * settings.time_step;
  const std::vector<double> rest(torsional.n_dofs(), 0.);
  const Trajectory trajectory = integrate(torsional, rest, rest, settings);
  const double initial = torsional.total_energy(0., rest.data(), rest.data());
  const std::size_t last = trajectory.size() - 1;
  const double strain = torsional.strain_energy(
      trajectory.time[last], trajectory.angle_at(last)); // the scale of the energies exchanged
  const double final = torsional.total_energy(trajectory.time[last], trajectory.angle_at(last),
                                              trajectory.velocity_at(last));
  ASSERT_GT(strain, 0.);
  EXPECT_NEAR(final, initial, 1e-6 * strain);
}

// Mesh phasing (Parker & Lin 2004, README): sun–planet copy n of N at ψ = 2πn/N runs
// frac(−z_s·n/N) behind copy 1 (sun turning positive relative to the carrier), the ring–planet
// mesh of the same planet ε_f,r − ε_f,s + (z_p + 1)/2 after its sun–planet mesh. Exact
// arithmetic on small fractions: 1e-12.
TEST(TrainModel, MeshPhases)
{
  const TrainModel model = build_train_model(planetary(3));
  ASSERT_EQ(model.train.meshes.size(), 6u);
  for (unsigned int n = 0; n < 3; ++n)
  {
    const double sun = model.train.meshes[n].initial_position;
    const double expected = -20. * n / 3.;
    EXPECT_NEAR(sun, expected - std::floor(expected), 1e-12);
    // The ring turns negative relative to the carrier: its copies run +|z_r|·n/N.
    const double ring = model.train.meshes[3 + n].initial_position;
    const double gamma =
        model.spec_mesh_approach_ratio[1] - model.spec_mesh_approach_ratio[0] + 5.5 + 40. * n / 3.;
    const double difference = ring - gamma - std::floor(ring - gamma);
    EXPECT_LT(std::min(difference, 1. - difference), 1e-12);
  }
}

// Seven planets in 20/10/−40: (z_s + |z_r|)/N = 60/7 is not whole, so they cannot be equally
// spaced; the model places them at the nearest assemblable angles 360°·round(60n/7)/60 and says so.
TEST(TrainModel, AssemblyConditionReported)
{
  const TrainModel model = build_train_model(planetary(7));
  ASSERT_EQ(model.notes.size(), 1u);
  EXPECT_NE(model.notes[0].find("cannot be equally spaced"), std::string::npos);
  EXPECT_NE(model.notes[0].find("0, 54, 102"), std::string::npos) << model.notes[0];
}

TEST(TrainModel, BadInput)
{
  TrainDynamicsInput input = planetary(3);
  input.spec.members[0].moment_of_inertia = 0.; // the sun
  try
  {
    build_train_model(input);
    FAIL() << "zero inertia accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(error.parameter(), "train.inertias");
  }
  input = planetary(3);
  input.spec.members[1].module = 0.; // the planet
  EXPECT_THROW(build_train_model(input), InputError);
  // A Train mesh's data the model refuses while it is built (its static forces need the model
  // before orientation): named as the Train mesh, not as the model's mesh number "mesh1.damping"
  // (the dynamics command checks the damping first, so only a library caller reaches this).
  try
  {
    build_train_model(planetary(3, 4e8, -1.));
    FAIL() << "negative damping accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(error.parameter(), "Train mesh 1/damping");
    EXPECT_NE(error.reason().find("must not be negative"), std::string::npos) << error.reason();
  }
}

// ISO 6336-1 method B per Train mesh (train_model.h TrainIsoPair). A one-mesh train on fixed
// axes is the single pair: m_red = m1·m2/(m1 + m2) with m = J/r_b² (the split path's
// reduced_mass), the pinion at the input speed, so the same K_v follows; a planetary stage with
// 3 planets gives 6.5.9's m_red = m_S·m_P/(m_S + 3·m_P) for sun–planet and m_P for the fixed
// ring. Same arithmetic in a different order: 1e-12 relative.
TEST(TrainModel, IsoPairsOfTrainMeshes)
{
  // The split-path pinion and one wheel: gears, modules, meshes, inputs, output and inertias.
  const kinematics::GearTrainText text{"1: 21, 2: 57",
                                       "1: 2.5, 2: 2.5",
                                       "",
                                       "",
                                       "1-2",
                                       "",
                                       "",
                                       "1: 1450",
                                       "2",
                                       "1: 1.47e-4, 2: 7.81e-3",
                                       "",
                                       ""};
  TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(text);
  input.input_torque = 49.4;
  input.meshes.push_back({MeshStiffness::constant(4e8, "m"), 100., 0., 0., 0., {}, {}, {}, {}});
  const TrainModel pair = build_train_model(input);
  ASSERT_EQ(pair.spec_mesh_iso.size(), 1u);
  const double r1 = 0.5 * 2.5e-3 * 21 * std::cos(input.pressure_angle);
  const double r2 = 0.5 * 2.5e-3 * 57 * std::cos(input.pressure_angle);
  const TrainIsoPair& iso = pair.spec_mesh_iso[0];
  EXPECT_NEAR(iso.reduced_mass, reduced_mass(1.47e-4, r1, 7.81e-3, r2), 1e-12 * iso.reduced_mass);
  EXPECT_EQ(iso.pinion_teeth, 21u);
  EXPECT_NEAR(iso.pinion_speed_ratio, 1., 1e-12);

  IsoDynamicFactorInput in;
  in.pinion_teeth = 21;
  in.pinion_speed = 1450. * M_PI / 30.;
  in.mesh_stiffness = 4e8 / 0.026;
  in.single_stiffness = in.mesh_stiffness / (0.75 * 1.6 + 0.25);
  in.face_width = 0.026;
  in.tangential_force = 2000.;
  in.total_contact_ratio = 1.6;
  in.pitch_deviation = in.profile_deviation = 8e-6;
  in.reduced_mass = reduced_mass(1.47e-4, r1, 7.81e-3, r2);
  const double split_path = iso6336_dynamic_factor(in).kv;
  in.reduced_mass = iso.reduced_mass;
  in.pinion_speed = iso.pinion_speed_ratio * 1450. * M_PI / 30.;
  EXPECT_NEAR(iso6336_dynamic_factor(in).kv, split_path, 1e-12 * split_path);

  // Planetary 20/10/−40, 3 planets: J_s = 2e-4, J_p = 5e-5 (planet copies turn alone).
  const TrainModel stage = build_train_model(planetary(3));
  const double rs = 0.5 * 2e-3 * 20 * std::cos(20. * M_PI / 180.);
  const double rp = 0.5 * 2e-3 * 10 * std::cos(20. * M_PI / 180.);
  const double ms = 2e-4 / (rs * rs), mp = 5e-5 / (rp * rp);
  EXPECT_NEAR(stage.spec_mesh_iso[0].reduced_mass, ms * mp / (ms + 3. * mp), 1e-12 * mp);
  EXPECT_NEAR(stage.spec_mesh_iso[1].reduced_mass, mp, 1e-12 * mp);
}

// Modal kinetic energy per body (the command's dynamics_modal_energy table): each mode's shares
// are non-negative and sum to 1 (the mass-weighted squares of one mode shape, divided by their
// sum: round-off only, 1e-12), for the bi-planetary train with ring 7 suspended.
TEST(TrainModel, ModalEnergySharesSumToOne)
{
  TrainDynamicsInput input = bi_planetary();
  input.suspensions.push_back({"7", 1e6, 0.});
  const TrainModel model = build_train_model(input);
  const TorsionalModel torsional(model.train);
  std::vector<std::string> bodies;
  std::vector<unsigned int> group;
  for (const std::string& body : model.dof_body)
  {
    const auto found = std::find(bodies.begin(), bodies.end(), body);
    group.push_back(found - bodies.begin());
    if (found == bodies.end())
      bodies.push_back(body);
  }
  const Eigen::MatrixXd share = modal_energy_distribution(torsional, group, bodies.size());
  ASSERT_EQ(share.rows(), static_cast<Eigen::Index>(model.dof_names.size()));
  for (Eigen::Index k = 0; k < share.rows(); ++k)
  {
    EXPECT_NEAR(share.row(k).sum(), 1., 1e-12) << "mode " << k;
    EXPECT_GE(share.row(k).minCoeff(), 0.);
  }
}

// A Train mesh of shifted gears (issue 41) has the contact ratio and approach ratio of the
// gear-pair module's pair with standard tips d + 2m(1 + x) at its zero-backlash centre
// distance: the own pair of the issue (z 23/61, m 4 mm, x 0.2/−0.1) and an internal pair
// (planet 24 in ring 69, x 0.3/0.5: a smaller ring shift interferes at the standard ring tip). Both
// modules evaluate the same involute geometry by their own formulas: 1e-12.
TEST(TrainModel, StandardMeshOfShiftedGearsIsTheGearPairs)
{
  const double alpha = 20. * M_PI / 180.;
  for (const auto& [z1, z2, x1, x2, internal] :
       {std::tuple{23, 61, 0.2, -0.1, false}, std::tuple{24, 69, 0.3, 0.5, true}})
  {
    const kinematics::GearPairGeometry pair =
        kinematics::compute_gear_pair(test_support::shifted_pair(z1, z2, x1, x2, internal));
    const kinematics::TrainMember a{"a", z1, 4e-3, "", 1, 0., 0., x1};
    const kinematics::TrainMember b{"b", internal ? -z2 : z2, 4e-3, "", 1, 0., 0., x2};
    const StandardMesh mesh = standard_mesh(a, b, alpha, 0);
    EXPECT_NEAR(mesh.contact_ratio, pair.transverse_contact_ratio, 1e-12) << z1 << "/" << z2;
    EXPECT_NEAR(mesh.approach_ratio,
                (pair.pitch_point - pair.contact_start) / pair.transverse_base_pitch, 1e-12)
        << z1 << "/" << z2;
  }
}
