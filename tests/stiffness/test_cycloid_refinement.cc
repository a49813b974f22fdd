// Refinement check of the cycloid drive's load distribution (issue 13): the built-in case
// (gear-data.md §4: i = 19, r = 96 mm, e = 3 mm, q = 8.5 mm, M_c = 440 N·m per disc), nominal
// profile, crank angle 0, solved on the default mesh and on the next level of the study in
// docs/cycloid.md ("Speed and discretisation": h_c 60 µm, body 1.2 mm, growth 0.3, 75k DoFs).
//
// Stated discretisation error of the default (docs/cycloid.md, against the finest level of the
// ladder, 124k DoFs: P_max 1436.7 N, Q_max 4011.2 N): P_max −1.3 %, Q_max −0.04 %. The ladder is
// monotone in P_max (1417.6 < 1422.4 < 1436.7 N): refining raises the largest roller force,
// because the finer disc ring between lobes and bore is softer and the load concentrates. The
// test asserts that direction and that the finer level moves P_max by less than the stated
// 1.5 % bound and Q_max by less than 0.1 % (0.04 % stated, plus room for gmsh's mesh-to-mesh
// scatter, which the study measured at ~0.05 % in Q_max).
#include "stiffness/cycloid_loads.h"
#include "tests/stiffness/work_file.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
CycloidLoadResult solve_level(const std::string& name, double contact_size, double body_size,
                              double growth_rate)
{
  CycloidLoadSettings s;
  s.crank_angle = 0.;
  s.output_torque = 440.; // N·m, one disc (gear-data.md §4)
  s.scene.mesh.contact_size = contact_size;
  s.scene.mesh.body_size = body_size;
  s.scene.mesh.growth_rate = growth_rate;
  s.scene_file = stiffness_work_stem(name) + ".msh";
  const CycloidLoadResult r = CycloidLoads<2>(s).run();
  std::filesystem::remove(s.scene_file);
  std::cout << name << ": " << r.n_dofs << " DoFs, P_max = " << r.max_roller_force
            << " N, Q_max = " << r.max_pin_force << " N, " << r.total_time << " s" << std::endl;
  return r;
}
} // namespace

TEST(CycloidRefinement, DefaultWithinStatedErrorOfFinerLevel)
{
  const CycloidLoadSettings defaults;
  const auto& mesh = defaults.scene.mesh;
  const CycloidLoadResult coarse =
      solve_level("cycloid-default", mesh.contact_size, mesh.body_size, mesh.growth_rate);
  const CycloidLoadResult fine = solve_level("cycloid-finer", 60e-6, 1.2e-3, 0.3);

  ASSERT_GT(fine.n_dofs, 1.3 * coarse.n_dofs); // the finer level really is finer
  EXPECT_GT(fine.max_roller_force, coarse.max_roller_force);
  EXPECT_LT(std::abs(coarse.max_roller_force / fine.max_roller_force - 1.), 0.015);
  EXPECT_LT(std::abs(coarse.max_pin_force / fine.max_pin_force - 1.), 1e-3);
  // Loaded counts are integers the discretisation must not change at this torque.
  EXPECT_EQ(coarse.loaded_rollers, fine.loaded_rollers);
  EXPECT_EQ(coarse.loaded_pins, fine.loaded_pins);
}
