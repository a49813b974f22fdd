// The gear-pair scene of the split-path gearbox (docs/references.md §1, Reszuta &
// Drewniak 2015): every mesh is read back with deal.II's GridIn::read_msh and checked for its ids,
// its cell size at the predicted contacts and the gaps along the line of action, measured on the
// boundary faces deal.II sees (not on the outlines the scene was built from).
#include "errors/errors.h"
#include "geometry/scene_gear_pair.h"
#include "tests/geometry/scene_test_support.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <set>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;
using namespace gearstiff::test_support;

// Boundary ids of the loaded flanks of pairs first..last on one gear (one id per flank).
std::set<int> flank_ids(bool wheel, int first, int last)
{
  std::set<int> ids;
  for (int j = first; j <= last; ++j)
    ids.insert(wheel ? wheel_flank_id(j) : pinion_flank_id(j));
  return ids;
}

// Distances along the line of action (from T1) where it crosses boundary faces with an id of
// `ids`.
std::vector<double> crossings(const dealii::Triangulation<2>& triangulation,
                              const std::set<int>& ids, const Eigen::Vector2d& t1,
                              const Eigen::Vector2d& t2)
{
  const Eigen::Vector2d u = (t2 - t1).normalized();
  const double length = (t2 - t1).norm();
  std::vector<double> result;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()) > 0)
      {
        const auto v0 = cell->face(f)->vertex(0), v1 = cell->face(f)->vertex(1);
        const Eigen::Vector2d a(v0[0], v0[1]), b(v1[0], v1[1]);
        Eigen::Matrix2d m;
        m << u, a - b;
        if (std::abs(m.determinant()) < 1e-30)
          continue;
        const Eigen::Vector2d ts = m.inverse() * (a - t1);
        if (ts(1) >= 0. && ts(1) < 1. && ts(0) >= 0. && ts(0) <= length)
          result.push_back(ts(0));
      }
  return result;
}

// Pinion/wheel flank crossings of the line of action that coincide within `tolerance`.
unsigned int touching_pairs(const dealii::Triangulation<2>& triangulation, const SceneInfo& info,
                            double tolerance, std::vector<double>* gaps = nullptr)
{
  const auto& line = info.reference_line;
  const int n = max_pair_index;
  const auto pinion = crossings(triangulation, flank_ids(false, -n, n), line[0], line[1]);
  const auto wheel = crossings(triangulation, flank_ids(true, -n, n), line[0], line[1]);
  unsigned int count = 0;
  for (const double p : pinion)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const double w : wheel)
      nearest = std::min(nearest, std::abs(w - p));
    if (gaps)
      gaps->push_back(nearest);
    if (nearest < tolerance)
      ++count;
  }
  return count;
}

// Longest edge of the cells that have a vertex within `radius` of `point`.
double largest_edge_near(const dealii::Triangulation<2>& triangulation,
                         const Eigen::Vector2d& point, double radius)
{
  double largest = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    bool near = false;
    for (const auto v : cell->vertex_indices())
      near |= (Eigen::Vector2d(cell->vertex(v)[0], cell->vertex(v)[1]) - point).norm() < radius;
    if (near)
      for (const auto f : cell->face_indices())
        largest = std::max(largest, cell->face(f)->measure());
  }
  return largest;
}

SceneInfo scene(const std::string& position, const std::string& name, unsigned int dimension = 2,
                RimModel rim = RimModel::sector)
{
  GearPairSceneSpec spec;
  spec.position = parse_pair_position(position, "position");
  spec.mesh.dimension = dimension;
  spec.mesh.layers = 3;
  spec.rim = rim;
  return write_gear_pair_scene(spec, work_file(name)).info;
}

// Gap below which a pair counts as touching (m). The scene places the flanks exactly; what
// remains is the spline through the profile points and the chord between boundary nodes:
// with h_c ≈ 5-8 µm and a flank curvature radius ≥ 5 mm the chord sag is below 1e-11 m, the
// spline error below 1e-7 m. 0.5 µm is still 12x smaller than the tooth-pair deflection at the
// published load (Δφ·r_b1 = 2.481e-4 · 24.667 mm ≈ 6.1 µm, docs/references.md §1), so a pair that
// is "near-zero" here is in contact for any FE analysis at that load.
constexpr double touching_tolerance = 0.5e-6;
// The gap to the next pair outside the path of contact is a sizeable fraction of the base
// pitch; 50 µm separates "touching" from "not touching" by two orders of magnitude.
constexpr double apart_tolerance = 50e-6;

// The contacts of a scene: `pairs` tooth pairs touch, every other crossing of the line of action
// is clearly apart, and the cells at each contact point have edges no longer than its h_c.
void expect_touching_and_resolved(const dealii::Triangulation<2>& triangulation,
                                  const SceneInfo& info, unsigned int pairs)
{
  std::vector<double> gaps;
  EXPECT_EQ(touching_pairs(triangulation, info, touching_tolerance, &gaps), pairs);
  for (const double gap : gaps)
    EXPECT_TRUE(gap < touching_tolerance || gap > apart_tolerance) << "gap " << gap;
  for (const auto& contact : info.contacts)
    EXPECT_LE(largest_edge_near(triangulation, contact.point, 0.5 * contact.contact_size),
              contact.contact_size);
}

TEST(GearPairScene, SinglePairPositionHasExactlyOneTouchingPair)
{
  const SceneInfo info = scene("single", "single.msh");
  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);

  const Ids ids = ids_of(triangulation);
  EXPECT_EQ(ids.materials, (std::set<int>{scene_ids::pinion_body, scene_ids::wheel_body}));
  // One id per loaded flank: five teeth per gear centred on pair 0 (pairs −2..2).
  std::set<int> expected{scene_ids::free_surface, scene_ids::pinion_bore, scene_ids::wheel_bore,
                         scene_ids::pinion_cuts, scene_ids::wheel_cuts};
  expected.merge(flank_ids(false, -2, 2));
  expected.merge(flank_ids(true, -2, 2));
  EXPECT_EQ(ids.boundaries, expected);
  EXPECT_EQ(triangulation.n_active_cells(), info.mesh.n_cells);

  // The split-path pair (ε_α = 1.5, docs/references.md §1) has its pitch point in the
  // single-contact zone, so "single" puts the one contact at the pitch point C: ℓ = r_b1·tan α_wt
  // with r_b1 = 24.667 mm and α_wt = 20° → 8.978 mm, 26.25 mm from the pinion axis (r_w1 = r1).
  ASSERT_EQ(info.contacts.size(), 1u);
  EXPECT_NEAR(info.contacts[0].point.norm(), 26.25e-3, 1e-6); // 1 µm: r_b1 is given to 1 µm
  // Hertz half-width at the pitch point ≈ 0.08 mm (docs/references.md §6: 2.0 kN over 24 mm); the
  // estimate is printed to one significant figure, so ±10 %.
  EXPECT_NEAR(info.contacts[0].hertz_half_width, 0.08e-3, 0.008e-3);
  EXPECT_NEAR(info.contact_size, 0.1 * info.contacts[0].hertz_half_width, 1e-12);

  expect_touching_and_resolved(triangulation, info, 1);

  EXPECT_GT(info.mesh.min_scaled_jacobian, 0.2); // the checker already rejects <= 0
}

TEST(GearPairScene, DoublePairPositionHasTwoTouchingPairs)
{
  const SceneInfo info = scene("double", "double.msh");
  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);
  ASSERT_EQ(info.contacts.size(), 2u);
  // The two contacts are one transverse base pitch apart: p_et = 7.380 mm (docs/references.md §1,
  // printed to 1 µm).
  EXPECT_NEAR((info.contacts[1].point - info.contacts[0].point).norm(), 7.380e-3, 1e-6);
  expect_touching_and_resolved(triangulation, info, 2);
}

TEST(GearPairScene, FullRimHasBoresAndNoCuts)
{
  const SceneInfo info = scene("single", "full.msh", 2, RimModel::full);
  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);
  const Ids ids = ids_of(triangulation);
  std::set<int> expected{scene_ids::free_surface, scene_ids::pinion_bore, scene_ids::wheel_bore};
  expected.merge(flank_ids(false, -2, 2));
  expected.merge(flank_ids(true, -2, 2));
  EXPECT_EQ(ids.boundaries, expected);
  EXPECT_EQ(touching_pairs(triangulation, info, touching_tolerance), 1u);
}

TEST(GearPairScene, ExtrudedSceneIsHexahedralWithSideFaces)
{
  const SceneInfo info = scene("single", "single3d.msh", 3);
  dealii::Triangulation<3> triangulation;
  read_mesh(triangulation, info.file);
  const Ids ids = ids_of(triangulation);
  EXPECT_EQ(ids.materials, (std::set<int>{scene_ids::pinion_body, scene_ids::wheel_body}));
  std::set<int> expected{scene_ids::pinion_bore, scene_ids::wheel_bore, scene_ids::pinion_cuts,
                         scene_ids::wheel_cuts,  scene_ids::side_faces, scene_ids::free_surface};
  expected.merge(flank_ids(false, -2, 2));
  expected.merge(flank_ids(true, -2, 2));
  EXPECT_EQ(ids.boundaries, expected);
  EXPECT_EQ(triangulation.n_active_cells(), info.mesh.n_cells);
  // Face width of the split-path pair: the common width min(26, 24) mm (docs/references.md §1).
  EXPECT_DOUBLE_EQ(info.face_width, 24e-3);
  // The extrusion copies the 2D mesh into `layers` layers.
  const SceneInfo flat = scene("single", "single_for_3d.msh");
  EXPECT_EQ(info.mesh.n_cells, 3 * flat.mesh.n_cells);
}

// Fine sweeps (64-256 positions, stiffness/mesh_stiffness_sweep.h: ℓ_i = A + (i + ½)·p_bt/N)
// put a contact within p_bt/(2N) of an end of the path of contact: at the first position the
// reference pair touches next to the wheel's tip corner, near the middle of the sweep pair +1
// next to the pinion's. The scene must place and mesh these flanks like any other, with every
// pair the kinematics counts touching (issue 11: they failed with "the line of action misses
// a flank" because the flank piece next to the tip corner was labelled tip).
TEST(GearPairScene, FineSweepPositionsNearThePathEndsTouch)
{
  GearPairSceneSpec spec;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  spec.position = PairPosition::roll_angle;
  for (const unsigned int n : {64u, 256u})
    for (const unsigned int i : {0u, n / 2 - 1, n / 2, n - 1})
    {
      const double position = pair.contact_start + (i + 0.5) * pair.transverse_base_pitch / n;
      spec.pinion_roll_angle = position / r_b1;
      SceneInfo info;
      ASSERT_NO_THROW(info = write_gear_pair_scene(spec, work_file("sweep_end.msh")).info)
          << "position " << i << " of " << n;
      EXPECT_EQ(info.contacts.size(), pair.pairs_in_contact(position));
      dealii::Triangulation<2> triangulation;
      read_mesh(triangulation, info.file);
      EXPECT_EQ(touching_pairs(triangulation, info, touching_tolerance), info.contacts.size())
          << "position " << i << " of " << n;
    }
}

TEST(GearPairScene, RejectsBadInputBeforeMeshing)
{
  const std::string file = work_file("rejected.msh");
  std::filesystem::remove(file);
  GearPairSceneSpec spec;
  // 95 mm is below the zero-backlash centre distance 97.5 mm: the teeth would interfere.
  spec.pair.centre_distance = 95e-3;
  EXPECT_THROW(write_gear_pair_scene(spec, file), InputError);
  spec = GearPairSceneSpec();
  spec.pinion_bore_radius = 23e-3; // leaves < 1 module of rim under the 23.85 mm root circle
  EXPECT_THROW(write_gear_pair_scene(spec, file), InputError);
  EXPECT_THROW(parse_pair_position("triple", "position"), InputError);
  spec = GearPairSceneSpec();
  spec.position = PairPosition::double_pair;
  spec.pinion_teeth_modelled = 1; // two pairs are in contact
  EXPECT_THROW(write_gear_pair_scene(spec, file), InputError);
  EXPECT_FALSE(std::filesystem::exists(file));
}
} // namespace
