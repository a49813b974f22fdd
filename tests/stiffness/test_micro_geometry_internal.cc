// Tooth modifications on an internal pair (issue 27): the planet–ring pair of planet_ring.h
// (z = 24 in 69, docs/references.md §2), 2D. The zero-load rule of the external pair
// (test_micro_geometry.cc) holds with the ring's own roll lengths (its distance from T2 on the
// line of action, geometry/gear_pair_contacts.cc): with equal linear long tip reliefs C on the
// planet and the ring the unloaded TE is the tent min(C·s, C·(1 − s)) in the first double zone
// [A, B] (the entering pair relieved by the ring tip, which bounds the path at A; the leaving one
// by the planet tip) and 0 in the single zone; relief on one gear only leaves 0 everywhere. The
// designed separations are checked on the mesh deal.II reads (the flank crossings of the line of
// action), and the FE TE at a near-zero torque against the geometric value.
#include "geometry/scene_gear_pair.h"
#include "tests/geometry/scene_test_support.h"
#include "tests/stiffness/long_relief.h"
#include "tests/stiffness/planet_ring.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
using test_support::long_relief;

geometry::GearPairSceneSpec ring_scene(double c_planet, double c_ring)
{
  geometry::GearPairSceneSpec spec = planet_ring_settings(3., "ring_relief").scene;
  if (c_planet > 0.)
    spec.pinion_modifications.all_teeth = {long_relief(c_planet)};
  if (c_ring > 0.)
    spec.wheel_modifications.all_teeth = {long_relief(c_ring)};
  spec.position = geometry::PairPosition::roll_angle;
  return spec;
}
} // namespace

// The tent on both gears, measured from the design and on the mesh (within 0.2 µm: the spline
// and chord error of the outline, as for the external pair in test_tooth_modification.cc). The
// ring's concave flank makes the relative radius large (24–28 mm): each pair touches β²R/2 below
// its removal at ℓ, 0.8 µm here (relieved_tent).
TEST(MicroGeometryInternal, UnloadedTentWithReliefOnPlanetAndRing)
{
  const double c = 10e-6;
  geometry::GearPairSceneSpec spec = ring_scene(c, c);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double a = pair.contact_start, b = pair.single_contact_start();
  const double rb1 = 0.5 * pair.pinion.base_diameter;
  const std::string file = stiffness_work_stem("ring_tent") + ".msh";
  for (const double s : {0.2, 0.5, 0.7})
  {
    spec.pinion_roll_angle = (a + s * (b - a)) / rb1;
    const geometry::GearPairScene scene = geometry::write_gear_pair_scene(spec, file);
    EXPECT_NEAR(scene.unloaded_transmission_error, test_support::relieved_tent(pair, s, c), 1e-12)
        << s;
    ASSERT_EQ(scene.contact_pairs.size(), 2u);
    dealii::Triangulation<2> triangulation;
    test_support::read_mesh(triangulation, file);
    const auto& line = scene.info.reference_line;
    for (std::size_t k = 0; k < scene.contact_pairs.size(); ++k)
    {
      const int j = scene.contact_pairs[k];
      const double gap =
          test_support::smallest_flank_gap(triangulation, geometry::pinion_flank_id(j),
                                           geometry::wheel_flank_id(j), line[0], line[1], 0.5e-3);
      EXPECT_NEAR(gap, scene.pair_separation[k], 0.2e-6) << "s = " << s << ", pair " << j;
    }
  }
  spec.pinion_roll_angle = 0.5 * (b + pair.single_contact_end()) / rb1;
  EXPECT_EQ(geometry::write_gear_pair_scene(spec, file).unloaded_transmission_error, 0.);
  std::filesystem::remove(file);
}

// Relief on one gear only (the ring, then the planet): the unmodified pair leads, 0 everywhere.
TEST(MicroGeometryInternal, ReliefOnOneGearHasNoUnloadedError)
{
  const std::string file = stiffness_work_stem("ring_one") + ".msh";
  for (const bool on_ring : {true, false})
  {
    geometry::GearPairSceneSpec spec = ring_scene(on_ring ? 0. : 10e-6, on_ring ? 10e-6 : 0.);
    const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
    const double rb1 = 0.5 * pair.pinion.base_diameter;
    for (const double s : {0.1, 0.4, 0.6, 0.9})
    {
      spec.pinion_roll_angle = (pair.contact_start + s * pair.transverse_base_pitch) / rb1;
      EXPECT_EQ(geometry::write_gear_pair_scene(spec, file).unloaded_transmission_error, 0.)
          << s << (on_ring ? " (ring)" : " (planet)");
    }
  }
  std::filesystem::remove(file);
}

// The FE at 0.5 N·m (a pair deflects ≈ 0.06 µm there: the external pair's 6 µm at 49.4 N·m
// scaled, the ring pair is stiffer still) at s = 0.3 of [A, B]: the leaving pair, relieved by
// C·s = 3 µm at ℓ, carries the load, the entering one (7 µm) nothing; the TE is the geometric
// error plus the small deflection (within 0.15 µm, as for the external pair). The geometric error
// is where the relieved flanks touch, 0.82 µm below the 3 µm (relieved_tent): until 2026-12-05
// the unloaded TE was the removal at ℓ, so this TE read 3.07 µm, 0.82 µm above the pinion's
// actual lag.
TEST(MicroGeometryInternal, ZeroLoadLimitIsTheGeometricError)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "ring_zero_load");
  settings.scene = ring_scene(10e-6, 10e-6);
  const kinematics::GearPairGeometry g = kinematics::compute_gear_pair(settings.scene.pair);
  settings.scene.pinion_roll_angle =
      (g.contact_start + 0.3 * (g.single_contact_start() - g.contact_start)) /
      (0.5 * g.pinion.base_diameter);
  settings.pinion_torque = 0.5;
  const GearMeshStiffnessResult r = run_and_remove_scene<2>(settings);
  const double geometric = test_support::relieved_tent(g, 0.3, 10e-6);
  EXPECT_NEAR(r.unloaded_transmission_error, geometric, 1e-12);
  EXPECT_GT(r.transmission_error, geometric);
  EXPECT_NEAR(r.transmission_error, geometric, 0.15e-6);
  for (const auto& load : r.pairs)
  {
    if (load.pair == 0) // the entering pair
    {
      EXPECT_LT(load.load_share, 1e-6);
    }
  }
}
