// FE stiffness results as plain data for the train model (dynamics/stiffness_file.h): reading
// the summary that `gearstiff stiffness`/`cai` write with -o (the layout of app/core/report.cc's
// Report::print_json, written here by hand with known numbers), the pair check, the cycle
// cover check, the reversal for the other gear driving, and gear-blank inertias.
#include "dynamics/stiffness_file.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "tests/dynamics/work_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;

namespace
{
// A summary for the sun–planet pair 20/10, m 2 mm, a_w 30 mm, with `n` sweep rows over `span`
// base pitches starting at 0.3 (so the positions wrap past 1), k = 400 + 100·cos(2πx) N/µm.
std::string write_summary(unsigned int n, double span, int wheel_teeth = 10)
{
  const std::string path = dynamics_work_file("summary-" + std::to_string(n) + "-" +
                                              std::to_string(wheel_teeth) + ".json");
  std::ofstream out(path);
  out.precision(17);
  out << "{\n  \"command\": \"stiffness\",\n  \"text\": {},\n  \"values\": {\n"
      << "    \"pinion_teeth\": {\"value\": 20, \"unit\": \"-\", \"description\": \"\"},\n"
      << "    \"wheel_teeth\": {\"value\": " << wheel_teeth
      << ", \"unit\": \"-\", \"description\": \"\"},\n"
      << "    \"transverse_module\": {\"value\": 2, \"unit\": \"mm\", \"description\": \"\"},\n"
      << "    \"centre_distance\": {\"value\": " << std::abs(20 + wheel_teeth)
      << ", \"unit\": \"mm\", \"description\": \"\"},\n"
      << "    \"contact_ratio\": {\"value\": 1.5, \"unit\": \"-\", \"description\": \"\"}\n"
      << "  },\n  \"tables\": {\n    \"stiffness_sweep\": {\"columns\": [\"position\", "
      << "\"mesh_position\", \"stiffness\"], \"units\": [\"-\", \"-\", \"N/um\"], \"rows\": [";
  for (unsigned int i = 0; i < n; ++i)
  {
    const double x = 0.3 + span * i / n;
    out << (i ? ", " : "") << "[" << i + 1 << ", " << x << ", "
        << 400. + 100. * std::cos(2. * M_PI * x) << "]";
  }
  out << "]}\n  },\n  \"files\": []\n}\n";
  return path;
}
} // namespace

// The table comes back modulo one pitch and sorted; values at its nodes x = frac(0.3 + i/16) are
// the written ones (17 digits written: 1e-12 relative).
TEST(StiffnessFile, ReadsSweepTable)
{
  const StiffnessFile file =
      read_stiffness_file(write_summary(16, 1.), "Train mesh 1/stiffness file");
  EXPECT_EQ(file.command, "stiffness");
  EXPECT_EQ(file.pair.pinion_teeth, 20);
  EXPECT_EQ(file.pair.wheel_teeth, 10);
  EXPECT_NEAR(file.pair.module, 2e-3, 1e-15);
  EXPECT_NEAR(file.pair.centre_distance, 30e-3, 1e-15);
  for (const unsigned int i : {0u, 5u, 11u, 15u})
  {
    const double x = std::fmod(0.3 + i / 16., 1.);
    const double k = file.stiffness.evaluate(x, 1.5, 0.5).stiffness;
    EXPECT_NEAR(k, (400. + 100. * std::cos(2. * M_PI * x)) * 1e6, 1e-12 * k) << x;
  }
}

// Half a base pitch of positions leaves a 0.5-pitch gap: not a mesh cycle.
TEST(StiffnessFile, RejectsPartialCycle)
{
  try
  {
    read_stiffness_file(write_summary(16, 0.5), "Train mesh 1/stiffness file");
    FAIL() << "no InputError";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "Train mesh 1/stiffness file");
    EXPECT_NE(std::string(e.what()).find("does not cover a mesh cycle"), std::string::npos);
  }
  EXPECT_THROW(read_stiffness_file("/nonexistent/summary.json", "p"), InputError);
}

// The pair check: 20/10 matches the mesh s-p in either order, not 20/11 nor a ring mesh.
TEST(StiffnessFile, PairCheck)
{
  const StiffnessFile file = read_stiffness_file(write_summary(8, 1.), "p");
  // a = m·|z_a + z_b|/2 without profile shifts: 30 mm for 20/10, 31 for 20/11, 37.5 at 2.5 mm.
  EXPECT_EQ(match_stiffness_file(file, 20, 10, 2e-3, 30e-3, "p"), 0u);
  EXPECT_EQ(match_stiffness_file(file, 10, 20, 2e-3, 30e-3, "p"), 1u);
  EXPECT_THROW(match_stiffness_file(file, 20, 11, 2e-3, 31e-3, "p"), InputError);
  EXPECT_THROW(match_stiffness_file(file, 20, 10, 2.5e-3, 37.5e-3, "p"), InputError);
  EXPECT_THROW(match_stiffness_file(file, 10, -40, 2e-3, 30e-3, "p"), InputError);
  // The same teeth with profile shifts that move the centres: another pair.
  EXPECT_THROW(match_stiffness_file(file, 20, 10, 2e-3, 30.5e-3, "p"), InputError);
  const StiffnessFile ring = read_stiffness_file(write_summary(8, 1., -40), "p");
  EXPECT_EQ(match_stiffness_file(ring, -40, 20, 2e-3, 20e-3, "p"), 1u);
}

// Reversal: k'(x) = k(frac(ε_α − x)) for a table, and the Cai bracket mirrored s → 1 − s; both
// exact identities (1e-12 relative: interpolation at mirrored nodes is the same arithmetic).
TEST(StiffnessFile, ReversedStiffness)
{
  const double eps = 1.63;
  const MeshStiffness table =
      MeshStiffness::table({0., 0.25, 0.5, 0.75}, {4e8, 3e8, 5e8, 2e8}, "t");
  const MeshStiffness back = table.reversed(eps);
  for (const double x : {0.0, 0.13, 0.38, 0.62, 0.88})
  {
    const double mirrored = eps - x - std::floor(eps - x);
    EXPECT_NEAR(back.evaluate(x, eps, 0.5).stiffness, table.evaluate(mirrored, eps, 0.5).stiffness,
                1e-12 * 5e8);
  }
  CaiParameters cai = cai_published_parameters(3e8);
  cai.shape = {0.5, 1.5, -1.2};
  const MeshStiffness curve = MeshStiffness::cai(cai, "c");
  const MeshStiffness mirrored = curve.reversed(eps);
  for (const double x : {0.1, 0.4, 0.9})
    EXPECT_NEAR(mirrored.evaluate(x, eps, 0.5).stiffness,
                curve.evaluate(eps - x - std::floor(eps - x), eps, 0.5).stiffness, 1e-6);
}

// Blanks: a solid disc of diameter d and width b has J = ρπb·d⁴/32 and m = ρπb·d²/4 (exact);
// a bore subtracts its disc; an internal gear needs an outer diameter.
TEST(StiffnessFile, BlankInertia)
{
  kinematics::TrainMember gear;
  gear.name = "s";
  gear.teeth = 20;
  gear.module = 2e-3;
  const double d = 0.04, b = 0.02, rho = 7850.;
  BlankInertia solid = blank_inertia(gear, {"s", b, 0.}, rho, "p");
  EXPECT_NEAR(solid.moment_of_inertia, rho * M_PI * b * std::pow(d, 4) / 32., 1e-15);
  EXPECT_NEAR(solid.mass, rho * M_PI * b * d * d / 4., 1e-12);
  BlankInertia bored = blank_inertia(gear, {"s", b, 0.01}, rho, "p");
  EXPECT_NEAR(bored.moment_of_inertia, rho * M_PI * b * (std::pow(d, 4) - std::pow(0.01, 4)) / 32.,
              1e-15);
  gear.teeth = -40;
  EXPECT_THROW(blank_inertia(gear, {"r", b, 0.}, rho, "p"), InputError);
  EXPECT_GT(blank_inertia(gear, {"r", b, 0.1}, rho, "p").moment_of_inertia, 0.);
}

// A file's own path of contact (e.g. a shortened ring tip: ε_α = 1.4, ε_f = 0.3 with its pinion
// driving) replaces the standard-tooth values of its Train mesh: the mesh cycle and the table's
// reversal use ε_α, and the approach ratio is ε_f when the FE pinion drives in the train, the
// FE recess ε_α − ε_f when the other gear does (contact starts at the other end). The two
// choices of FE pinion must give both, once each; exact arithmetic (1e-15).
TEST(StiffnessFile, FilePathOfContactReplacesStandardTeeth)
{
  kinematics::GearTrainText text = kinematics::builtin_train("planetary");
  text.inertias = "s: 2e-4, p: 5e-5, c: 4e-3, r: 1e-2";
  text.masses = "p: 0.4";
  std::vector<double> approach;
  for (const unsigned int fe_pinion : {0u, 1u})
  {
    TrainDynamicsInput input;
    input.spec = kinematics::parse_gear_train(text);
    input.input_torque = 100.;
    for (unsigned int m = 0; m < 2; ++m)
      input.meshes.push_back(
          {MeshStiffness::constant(4e8, "Train mesh/stiffness"), 0., 0., 0., 0., {}, {}, {}, {}});
    input.meshes[1].stiffness_driver = fe_pinion;
    input.meshes[1].contact_ratio = 1.4;
    input.meshes[1].approach_ratio = 0.3;
    const TrainModel model = build_train_model(input);
    EXPECT_EQ(model.spec_mesh_contact_ratio[1], 1.4);
    for (std::size_t i = 0; i < model.train.meshes.size(); ++i)
      EXPECT_EQ(model.train.meshes[i].contact_ratio,
                model.spec_mesh[i] == 1 ? 1.4 : model.spec_mesh_contact_ratio[0]);
    approach.push_back(model.spec_mesh_approach_ratio[1]);
  }
  std::sort(approach.begin(), approach.end());
  EXPECT_NEAR(approach[0], 0.3, 1e-15);
  EXPECT_NEAR(approach[1], 1.1, 1e-15);
}
