// Sensitivity of the split-path pair's mesh stiffness to the pinion bore, against the independent
// plane-strain FE model quoted in docs/references.md §1: enlarging the pinion bore
// radius from 10 to 15 mm raised the single-pair stiffness by about 7% and the double-pair
// stiffness by about 10%. The bore is not published for the ANSYS model, so this sensitivity is
// what bounds any comparison with it (tests/stiffness/test_mesh_stiffness.cc); here it is
// checked itself, under the published load case (T1 = 49.4 N·m, rigid pinion hub under torque,
// wheel bore fixed, μ = 0.01) on the default scene (2D plane strain, Q2, 3 teeth, full rims).
#include "stiffness/mesh_stiffness.h"
#include "tests/stiffness/work_file.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <mpi.h>
#include <unistd.h>

using namespace gearstiff;
using namespace gearstiff::contact;
using namespace gearstiff::stiffness;

namespace
{
double pair_stiffness(const std::string& position, double pinion_bore_radius)
{
  GearMeshStiffnessSettings settings;
  settings.scene.position = geometry::parse_pair_position(position, "position");
  settings.scene.pinion_bore_radius = pinion_bore_radius; // m
  settings.contact.friction_coefficient = 0.01;           // docs/references.md §1
  settings.scene_file = stiffness_work_stem("bore") + ".msh";
  GearMeshStiffness<2> analysis(MPI_COMM_SELF, settings);
  const GearMeshStiffnessResult r = analysis.run();
  std::filesystem::remove(settings.scene_file);
  std::cout << std::setprecision(6) << position << ", pinion bore radius "
            << pinion_bore_radius * 1e3 << " mm: k = " << r.mesh_stiffness / 1e6 << " N/um\n";
  return r.mesh_stiffness;
}
} // namespace

// "About 7%" and "about 10%" are whole percents, ±0.5 points; the two models also differ in mesh,
// rim and hub details that the source does not give, so ±1 point is allowed. Measured: +6.75%
// and +9.70%.
TEST(BoreSensitivity, MatchesTheIndependentPlaneStrainModel)
{
  const double single_ratio = pair_stiffness("single", 15e-3) / pair_stiffness("single", 10e-3);
  EXPECT_NEAR(single_ratio, 1.07, 0.01);
  const double double_ratio = pair_stiffness("double", 15e-3) / pair_stiffness("double", 10e-3);
  EXPECT_NEAR(double_ratio, 1.10, 0.01);
  // The double pair shares the hub's rotation between two tooth pairs, so the bore's share of
  // its compliance is larger: it must be the more sensitive of the two, as in the source.
  EXPECT_GT(double_ratio, single_ratio);
}
