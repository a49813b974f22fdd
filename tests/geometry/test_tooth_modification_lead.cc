// Lead modifications (issue 27; geometry/tooth_modification_lead.h) on the split-path pair of
// docs/references.md §1 in a coarse 3D scene: the µm change is on the mesh deal.II reads back
// (every flank vertex lies δ(z) below the nominal involute, measured along the flank normal), a
// zero lead modification writes today's mesh byte for byte, the unloaded transmission error
// takes the smallest summed lead removal, and bad input names its parameter.
#include "errors/errors.h"
#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_modification_lead.h"
#include "kinematics/gear_pair.h"
#include "tests/geometry/scene_test_support.h"
#include "tests/kinematics/planet_ring_pair.h"

#include <algorithm>
#include <cmath>
#include <deal.II/grid/tria.h>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;
using namespace gearstiff::test_support;

// A coarse 3D scene (8 layers): the lead shapes need the layers, not fine transverse cells.
GearPairSceneSpec coarse_3d()
{
  GearPairSceneSpec spec;
  spec.mesh.dimension = 3;
  spec.mesh.layers = 8;
  spec.mesh.contact_size = 2e-4;
  spec.mesh.fine_radius = 4e-4;
  spec.mesh.body_size = 1e-3;
  return spec;
}

ToothProfile nominal_tooth(const GearPairSceneSpec& spec, bool wheel)
{
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const auto& gear = wheel ? spec.pair.wheel : spec.pair.pinion;
  const double tip = wheel ? pair.wheel.tip_diameter : pair.pinion.tip_diameter;
  return generate_involute_tooth(involute_tooth_spec(gear, tip), spec.resolution);
}

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct FlankCheck
{
  double largest_error = 0.;  // m, |depth − δ(z)| over the flank vertices
  double smallest_depth = 1.; // m, of the designed δ(z) at the vertices
  double largest_depth = 0.;  // m
  unsigned int vertices = 0;
};

// Every vertex of the faces with `boundary_id` on the involute part (form circle to tip) of its
// tooth: its depth below the nominal flank of its side (r_b times the angle between the involute
// through it and the flank's, geometry/tooth_modification_lead.h) against δ(z) of that side.
FlankCheck check_flank(const dealii::Triangulation<3>& triangulation, int boundary_id,
                       const ToothProfile& tooth, const Eigen::Vector2d& centre, double rotation,
                       const LeadModification& lead, double face_width)
{
  const LeadModifier measure(tooth, LeadModification(), 1, face_width, centre, rotation, "test");
  FlankCheck check;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto& face : cell->face_iterators())
    {
      if (!face->at_boundary() ||
          face->boundary_id() != static_cast<dealii::types::boundary_id>(boundary_id))
        continue;
      for (unsigned int v = 0; v < face->n_vertices(); ++v)
      {
        const auto& x = face->vertex(v);
        const Eigen::Vector2d p(x[0], x[1]);
        const double r = (p - centre).norm();
        // The involute part: form circle to tip (a ring's tip lies inside its form circle).
        if (r <= std::min(tooth.form_radius, tooth.tip_radius) + 1e-6 ||
            r >= std::max(tooth.form_radius, tooth.tip_radius) - 1e-6)
          continue;
        const double upper = measure.depth_below_flank(p, +1);
        const double lower = measure.depth_below_flank(p, -1);
        const int side = std::abs(upper) < std::abs(lower) ? +1 : -1;
        const double expected = lead_removed_depth(lead, x[2], face_width, side == +1);
        check.largest_error =
            std::max(check.largest_error, std::abs((side > 0 ? upper : lower) - expected));
        check.smallest_depth = std::min(check.smallest_depth, expected);
        check.largest_depth = std::max(check.largest_depth, expected);
        ++check.vertices;
      }
    }
  return check;
}

// The scene of `spec` written and read back by deal.II, both gears' loaded flanks of pair 0
// checked against their lead modifications (printed), and the scene's unloaded TE.
struct SceneCheck
{
  FlankCheck pinion, wheel;
  double unloaded_transmission_error = 0.; // m
};
SceneCheck check_scene(const GearPairSceneSpec& spec, const std::string& name)
{
  const std::string file = work_file(name);
  const GearPairScene scene = write_gear_pair_scene(spec, file);
  dealii::Triangulation<3> triangulation;
  read_mesh(triangulation, file);
  const double b = kinematics::compute_gear_pair(spec.pair).common_face_width;
  SceneCheck check;
  check.pinion = check_flank(triangulation, pinion_flank_id(0), nominal_tooth(spec, false),
                             scene.info.first_centre, scene.info.first_rotation,
                             spec.pinion_modifications.lead, b);
  check.wheel = check_flank(triangulation, wheel_flank_id(0), nominal_tooth(spec, true),
                            scene.info.second_centre, scene.info.second_rotation,
                            spec.wheel_modifications.lead, b);
  check.unloaded_transmission_error = scene.unloaded_transmission_error;
  for (const auto& [label, gear] :
       {std::pair{"pinion", check.pinion}, std::pair{"wheel", check.wheel}})
    std::cout << name << ", " << label << ": " << gear.vertices << " vertices, error "
              << gear.largest_error * 1e6 << " µm over " << gear.smallest_depth * 1e6 << "…"
              << gear.largest_depth * 1e6 << " µm\n";
  return check;
}

// Crowning C_β = 20 µm on both flanks of one gear, slope f_Hβ = 10 µm on the loaded flank of the
// other (the two tests below): the removal on the flank vertices and the unloaded TE. Unloaded TE
// at the single-contact position (no profile modification): the smallest over z of
// C_β(2u − 1)² + f_Hβ·u, u = z/b: at u = 1/2 − f_Hβ/(8C_β) = 0.4375 it is
// 20·0.0625² + 10·0.4375 = 4.6875 µm (the 2001-point sample is within 1e-12 m of it there).
void expect_crowning_and_slope(const FlankCheck& crowned, const FlankCheck& sloped,
                               double unloaded_transmission_error)
{
  EXPECT_GT(crowned.vertices, 100u);
  EXPECT_GT(sloped.vertices, 100u);
  EXPECT_NEAR(crowned.smallest_depth, 0., 1e-12); // the middle layer z = b/2
  EXPECT_NEAR(crowned.largest_depth, 20e-6, 1e-12);
  EXPECT_NEAR(sloped.largest_depth, 10e-6, 1e-12);
  EXPECT_LT(crowned.largest_error, 0.05e-6);
  EXPECT_LT(sloped.largest_error, 0.05e-6);
  EXPECT_NEAR(unloaded_transmission_error, 4.6875e-6, 1e-11);
}

// Pinion crowning C_β = 20 µm on both flanks, wheel slope f_Hβ = 10 µm on its loaded flank. The
// designed removal spans 0…20 µm across the face (pinion) and 0…10 µm (wheel); the flank
// vertices deal.II reads sit within 0.05 µm of it: the vertices lie on gmsh's splines through
// exact involute points (tooth_profile.h; the 2D chord error ≈ 0.01 µm, test_tooth_modification),
// turned by φ = δ/r_b exactly (an involute turned about its axis is the parallel involute).
// Crowning C_β = 20 µm on both flanks of one gear (the wheel when `wheel_crowned`), slope
// f_Hβ = 10 µm on the loaded flank of the other, checked on the mesh deal.II reads.
void check_crowning_and_slope(GearPairSceneSpec spec, bool wheel_crowned, const std::string& file)
{
  LeadModification& crowned =
      (wheel_crowned ? spec.wheel_modifications : spec.pinion_modifications).lead;
  LeadModification& sloped =
      (wheel_crowned ? spec.pinion_modifications : spec.wheel_modifications).lead;
  crowned.crowning = 20e-6;
  sloped.slope = 10e-6;
  sloped.flanks = ModifiedFlanks::loaded;
  const SceneCheck check = check_scene(spec, file);
  expect_crowning_and_slope(wheel_crowned ? check.wheel : check.pinion,
                            wheel_crowned ? check.pinion : check.wheel,
                            check.unloaded_transmission_error);
}

TEST(LeadModification, MicrometresOnTheMeshDealIIReads)
{
  check_crowning_and_slope(coarse_3d(), false, "lead_crowning_3d.msh");
}

// The planet–ring pair of tests/kinematics/planet_ring_pair.h (z = 24 in 69, m = 2.5 mm, ring
// addendum 0.5·m, a rim of 3 modules) in the coarse 3D scene.
GearPairSceneSpec planet_ring_3d()
{
  GearPairSceneSpec spec = coarse_3d();
  test_support::make_planet_ring(spec.pair);
  spec.wheel_rim_thickness = 3. * 2.5e-3;
  return spec;
}

// Lead modifications on a ring (geometry/tooth_modification_lead.h: the same turn about the gear
// axis; the ring's flanks unwind the other way). Ring crowning C_β = 20 µm on both flanks, planet
// slope f_Hβ = 10 µm on its loaded flank: the ring's flank vertices on the mesh deal.II reads sit
// within 0.05 µm of the designed removal (the same bound and reason as the external pair above:
// measured 2026-11-26 in the output), and the unloaded TE takes the same smallest summed removal,
// 4.6875 µm (derivation above: the sum does not depend on which gear carries which shape).
TEST(LeadModification, RingMicrometresOnTheMesh)
{
  check_crowning_and_slope(planet_ring_3d(), true, "lead_ring_3d.msh");
}

// Zero lead modifications (whatever the flank choice) write today's 3D mesh byte for byte.
TEST(LeadModification, ZeroIsTodaysMesh)
{
  GearPairSceneSpec spec = coarse_3d();
  const std::string plain = work_file("lead_plain_3d.msh");
  write_gear_pair_scene(spec, plain);
  spec.pinion_modifications.lead.flanks = ModifiedFlanks::loaded;
  spec.wheel_modifications.lead.end_relief_length = 2e-3;
  const std::string zero = work_file("lead_zero_3d.msh");
  write_gear_pair_scene(spec, zero);
  EXPECT_EQ(file_text(plain), file_text(zero));
}

// Bad input names the gear's field (app maps "pinion.lead_slope" to "Gear pair/Pinion/lead slope",
// tests/stiffness cli cases) before anything is meshed.
TEST(LeadModification, BadInput)
{
  const auto fails = [](GearPairSceneSpec spec, const std::string& parameter)
  {
    try
    {
      check_tooth_modifications(spec);
      write_gear_pair_scene(spec, work_file("lead_bad.msh"));
      ADD_FAILURE() << "accepted " << parameter;
    }
    catch (const InputError& e)
    {
      EXPECT_EQ(e.parameter(), parameter) << e.what();
    }
  };
  GearPairSceneSpec spec = coarse_3d();
  spec.pinion_modifications.lead.end_relief = 5e-6; // no length
  fails(spec, "pinion.end_relief_length");
  spec.pinion_modifications.lead.end_relief_length = 20e-3; // beyond half the 24 mm face
  fails(spec, "pinion.end_relief_length");
  spec = coarse_3d();
  spec.wheel_modifications.lead.crowning = -5e-6;
  fails(spec, "wheel.lead_crowning");
  spec.wheel_modifications.lead.crowning = 2e-3; // 2 mm: beyond the tip thickness
  fails(spec, "wheel.lead_crowning");
  spec = coarse_3d();
  spec.mesh.dimension = 2;
  spec.pinion_modifications.lead.slope = 5e-6;
  fails(spec, "pinion.lead_slope");
  // On a ring the same checks apply: crowning beyond its tip thickness.
  spec = planet_ring_3d();
  spec.wheel_modifications.lead.crowning = 2e-3;
  fails(spec, "wheel.lead_crowning");
}
} // namespace
