// Refinement check of the cycloid drive's load distribution (issue 13): the built-in case
// (docs/references.md §4: i = 19, r = 96 mm, e = 3 mm, q = 8.5 mm, M_c = 440 N·m per disc), nominal
// profile, crank angle 0, Q2 (the default), solved on the default mesh and on the next level of
// the study in docs/cycloid.md ("Speed and discretisation"): every size of the size field —
// contact size, body size, rim size and growth rate — times 0.7.
//
// The study's ladder (factors 1, 0.7, 0.5, 0.35; 180k, 343k, 645k, 1.22 M DoFs) gave P_max
// 1426.3, 1429.4, 1432.7, 1433.4 N and Q_max 4010.0, 4009.8, 4010.0, 4009.6 N. Stated
// discretisation error of the default against the finest level: P_max −0.5 %, Q_max +0.01 %.
// Refining raises P_max (the finer disc ring between lobes and bore is softer and the load
// concentrates); the test asserts that direction, that the finer level moves P_max by less than
// the 1 % the issue allows (0.2 % measured) and Q_max by less than 0.1 % (gmsh's mesh-to-mesh
// scatter in Q_max is ~0.01 %), and that the loaded roller and pin counts stay.
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
CycloidLoadResult solve_level(const std::string& name, double factor)
{
  CycloidLoadSettings s;
  s.crank_angle = 0.;
  s.output_torque = 440.; // N·m, one disc (docs/references.md §4)
  auto& mesh = s.scene.mesh;
  mesh.contact_size *= factor;
  mesh.body_size *= factor;
  mesh.rim_size *= factor;
  mesh.growth_rate *= factor;
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
  ASSERT_EQ(CycloidLoadSettings().elasticity.degree, 2u); // the study is of the Q2 default
  const CycloidLoadResult coarse = solve_level("cycloid-default", 1.);
  const CycloidLoadResult fine = solve_level("cycloid-finer", 0.7);

  ASSERT_GT(fine.n_dofs, 1.5 * coarse.n_dofs); // the finer level really is finer
  EXPECT_GT(fine.max_roller_force, coarse.max_roller_force);
  EXPECT_LT(std::abs(coarse.max_roller_force / fine.max_roller_force - 1.), 0.01);
  EXPECT_LT(std::abs(coarse.max_pin_force / fine.max_pin_force - 1.), 1e-3);
  // Loaded counts are integers the discretisation must not change at this torque.
  EXPECT_EQ(coarse.loaded_rollers, fine.loaded_rollers);
  EXPECT_EQ(coarse.loaded_pins, fine.loaded_pins);
}
