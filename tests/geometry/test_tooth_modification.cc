// The modification stage of the tooth outlines (geometry/tooth_modification.h) on the split-path
// pair (docs/references.md §1): the relief shapes, healthy teeth bit-identical to the nominal
// outline, the modified flank δ inside the nominal one, and the unloaded transmission error of
// the scene against its geometric value (issue 27), measured both from the designed removal and
// on the mesh deal.II reads back.
#include "errors/errors.h"
#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_modification.h"
#include "geometry/tooth_profiles.h"
#include "kinematics/gear_pair.h"
#include "tests/geometry/scene_test_support.h"
#include "tests/kinematics/planet_ring_pair.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;
using namespace gearstiff::test_support;

ToothModification relief(ModificationKind kind, double amount, double length = -1.,
                         ReliefShape shape = ReliefShape::linear)
{
  ToothModification m;
  m.kind = kind;
  m.amount = amount;
  m.length = length;
  m.shape = shape;
  return m;
}

struct Gear
{
  kinematics::GearPairGeometry pair;
  ToothProfile tooth;
  FlankRollRange range;
};

// The pinion (`wheel` false) or the wheel of `spec`'s pair, its tooth and flank roll range.
Gear gear(const GearPairSceneSpec& spec, bool wheel)
{
  Gear g;
  g.pair = kinematics::compute_gear_pair(spec.pair);
  const kinematics::GearSpec& gear = wheel ? spec.pair.wheel : spec.pair.pinion;
  const double tip = wheel ? g.pair.wheel.tip_diameter : g.pair.pinion.tip_diameter;
  g.tooth = generate_involute_tooth(involute_tooth_spec(gear, tip), spec.resolution);
  g.range = flank_roll_range(g.pair, g.tooth, wheel);
  return g;
}

Gear pinion(const GearPairSceneSpec& spec = GearPairSceneSpec())
{
  return gear(spec, false);
}

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Shapes at the relief start (u = 0), its middle and the tip end (u = 1), by their definitions
// in tooth_modification.h (ISO 21771 linear and parabolic relief; the arc tangent at the start).
TEST(ToothModification, ReliefShapes)
{
  FlankRollRange range;
  range.tip = 10e-3;
  range.form = 2e-3;
  range.active_tip = 10e-3;
  range.active_root = 3e-3;
  const double c = 10e-6, length = 2e-3;
  for (const auto& [shape, middle] :
       {std::pair{ReliefShape::linear, 0.5 * c}, std::pair{ReliefShape::parabolic, 0.25 * c}})
  {
    const std::vector<ToothModification> list{
        relief(ModificationKind::tip_relief, c, length, shape)};
    EXPECT_EQ(removed_depth(list, range, range.tip, true), c);
    EXPECT_NEAR(removed_depth(list, range, range.tip - 0.5 * length, true), middle, 1e-18);
    EXPECT_EQ(removed_depth(list, range, range.tip - length, true), 0.);
    EXPECT_EQ(removed_depth(list, range, range.tip - 1.5 * length, true), 0.);
  }
  // Arc through C at the tip, tangent at the start: x²/(2R) with R = (L² + C²)/(2C), which at
  // mid-length differs from the parabola's C/4 by C³/(4L²)-order terms (2.5e-11 m here).
  const std::vector<ToothModification> arc{
      relief(ModificationKind::tip_relief, c, length, ReliefShape::arc)};
  EXPECT_NEAR(removed_depth(arc, range, range.tip, true), c, 1e-15);
  EXPECT_NEAR(removed_depth(arc, range, range.tip - 0.5 * length, true), 0.25 * c, 1e-10);
  // Root relief from the form circle; crowning C_α at both ends of the active profile, 0 in
  // its middle; slope f_Hα from 0 at the active root to f_Hα at the active tip.
  const std::vector<ToothModification> root{relief(ModificationKind::root_relief, c, length)};
  EXPECT_EQ(removed_depth(root, range, range.form, true), c);
  EXPECT_NEAR(removed_depth(root, range, range.form + 0.5 * length, true), 0.5 * c, 1e-18);
  const std::vector<ToothModification> crowning{relief(ModificationKind::profile_crowning, c, 0.)};
  EXPECT_NEAR(removed_depth(crowning, range, range.active_tip, true), c, 1e-18);
  EXPECT_NEAR(removed_depth(crowning, range, range.active_root, true), c, 1e-18);
  EXPECT_NEAR(removed_depth(crowning, range, 6.5e-3, true), 0., 1e-20);
  const std::vector<ToothModification> slope{relief(ModificationKind::profile_slope, c, 0.)};
  EXPECT_NEAR(removed_depth(slope, range, range.active_tip, true), c, 1e-18);
  EXPECT_EQ(removed_depth(slope, range, range.active_root, true), 0.);
  // Loaded flank only: the other flank keeps its material.
  std::vector<ToothModification> loaded = arc;
  loaded.front().flanks = ModifiedFlanks::loaded;
  EXPECT_EQ(removed_depth(loaded, range, range.tip, false), 0.);
}

// A tooth without modifications is the nominal outline object itself; a modified tooth moves
// only its flank points, each by δ(ρ) along its nominal normal, so its distance from the nominal
// flank polyline is δ up to the chord sag s²/(8ρ) of that polyline, which only the inserted
// relief start (on the exact involute between two points) shows: ≈ 4e-8 m for the ≈ 50 µm point
// spacing on ρ ≈ 10 mm.
TEST(ToothModification, HealthyTeethNominalAndFlankInset)
{
  const Gear g = pinion();
  GearModifications modifications;
  const double c = 12e-6;
  modifications.by_tooth[2] = {relief(ModificationKind::tip_relief, c)};
  const ToothProfiles teeth(g.tooth, modifications, g.range, +1, "pinion");
  EXPECT_EQ(&teeth.tooth(0), &teeth.nominal());
  EXPECT_EQ(&teeth.tooth(-1), &teeth.nominal());
  const ToothProfile& modified = teeth.tooth(2);
  ASSERT_NE(&modified, &teeth.nominal());
  // One point more per flank: the start of the relief.
  EXPECT_EQ(modified.points.size(), g.tooth.points.size() + 2);
  const double rb = g.tooth.base_radius;
  unsigned int relief_points = 0;
  double largest_error = 0.;
  for (const ProfilePoint& p : modified.points)
  {
    if (p.segment != ProfileSegment::relief && p.segment != ProfileSegment::flank)
      continue;
    relief_points += p.segment == ProfileSegment::relief;
    const double roll = std::sqrt(p.position.squaredNorm() - rb * rb);
    const double expected = teeth.loaded_flank_removal(2, roll);
    double nearest = 1e300;
    for (std::size_t i = 0; i + 1 < g.tooth.points.size(); ++i)
    {
      const ProfilePoint& a = g.tooth.points[i];
      const ProfilePoint& b = g.tooth.points[i + 1];
      if (a.side != p.side || b.side != p.side)
        continue;
      const Eigen::Vector2d ab = b.position - a.position;
      const double t = std::clamp((p.position - a.position).dot(ab) / ab.squaredNorm(), 0., 1.);
      nearest = std::min(nearest, (a.position + t * ab - p.position).norm());
    }
    largest_error = std::max(largest_error, std::abs(nearest - expected));
  }
  EXPECT_GT(relief_points, 10u);
  EXPECT_LT(largest_error, 1e-7);
}

// The scene with modifications on a tooth it does not model writes the same mesh, byte for
// byte, as the scene without any (the stage leaves healthy teeth untouched).
TEST(ToothModification, UnmodelledToothLeavesMeshUnchanged)
{
  GearPairSceneSpec spec;
  const std::string plain = work_file("modification_plain.msh");
  write_gear_pair_scene(spec, plain);
  spec.pinion_modifications.by_tooth[9] = {relief(ModificationKind::tip_relief, 10e-6)};
  const std::string other = work_file("modification_tooth9.msh");
  write_gear_pair_scene(spec, other);
  EXPECT_EQ(file_text(plain), file_text(other));
}

// Zero-load limit (issue 27): the unloaded TE is the smallest designed separation of the pairs.
// Equal linear long reliefs C on both gears: in the first double zone [A, B] the entering pair is
// relieved by the wheel tip, C·(1 − s), the leaving one by the pinion tip at ℓ + p_bt, C·s
// (D = A + p_bt), s = (ℓ − A)/(B − A): the tent min(C·s, C·(1 − s)) rising to C/2 in the middle,
// each pair lowered by β²R/2 where its relieved flanks touch (relieved_tent; 0.11–0.14 µm here,
// geometry::touching_point); 0 in the single zone. Each pair's separation measured on the mesh
// deal.II reads (the smallest gap between its flank faces along lines parallel to the line of
// action) agrees within the spline and chord error of the outline (< 0.2 µm,
// test_scene_gear_pair.cc).
TEST(ToothModification, UnloadedTransmissionErrorTent)
{
  GearPairSceneSpec spec;
  const double c = 10e-6;
  spec.pinion_modifications.all_teeth = {relief(ModificationKind::tip_relief, c)};
  spec.wheel_modifications.all_teeth = {relief(ModificationKind::tip_relief, c)};
  spec.position = PairPosition::roll_angle;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double a = pair.contact_start, b = pair.single_contact_start();
  const double rb1 = 0.5 * pair.pinion.base_diameter;
  for (const double s : {0.2, 0.5, 0.7})
  {
    spec.pinion_roll_angle = (a + s * (b - a)) / rb1;
    const std::string file = work_file("modification_tent.msh");
    const GearPairScene scene = write_gear_pair_scene(spec, file);
    EXPECT_NEAR(scene.unloaded_transmission_error, relieved_tent(pair, s, c), 1e-12) << s;
    ASSERT_EQ(scene.contact_pairs.size(), 2u);
    dealii::Triangulation<2> triangulation;
    read_mesh(triangulation, file);
    const auto& line = scene.info.reference_line;
    for (std::size_t k = 0; k < scene.contact_pairs.size(); ++k)
    {
      const int j = scene.contact_pairs[k];
      const double gap = smallest_flank_gap(triangulation, pinion_flank_id(j), wheel_flank_id(j),
                                            line[0], line[1], 0.5e-3);
      EXPECT_NEAR(gap, scene.pair_separation[k], 0.2e-6) << "s = " << s << ", pair " << j;
    }
  }
  spec.pinion_roll_angle = 0.5 * (b + pair.single_contact_end()) / rb1;
  EXPECT_EQ(
      write_gear_pair_scene(spec, work_file("modification_tent.msh")).unloaded_transmission_error,
      0.);
}

// Relief on one gear only: the unmodified pair leads everywhere, the unloaded TE is 0.
TEST(ToothModification, ReliefOnOneGearHasNoUnloadedError)
{
  GearPairSceneSpec spec;
  spec.pinion_modifications.all_teeth = {relief(ModificationKind::tip_relief, 10e-6)};
  spec.position = PairPosition::roll_angle;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double rb1 = 0.5 * pair.pinion.base_diameter;
  for (const double s : {0.1, 0.4, 0.6, 0.9})
  {
    spec.pinion_roll_angle = (pair.contact_start + s * pair.transverse_base_pitch) / rb1;
    EXPECT_EQ(
        write_gear_pair_scene(spec, work_file("modification_one.msh")).unloaded_transmission_error,
        0.)
        << s;
  }
}

// Bad input names the parameter (exit 2 in the commands).
TEST(ToothModification, BadInput)
{
  const Gear g = pinion();
  const auto fails = [&](const ToothModification& m, const std::string& parameter)
  {
    try
    {
      check_modifications({m}, g.tooth, g.range, "pinion");
      ADD_FAILURE() << "accepted " << parameter;
    }
    catch (const InputError& e)
    {
      EXPECT_EQ(e.parameter(), parameter);
    }
  };
  const double active = g.range.active_tip - g.range.active_root;
  fails(relief(ModificationKind::tip_relief, 5e-6, 1.01 * active), "pinion.tip_relief_length");
  fails(relief(ModificationKind::root_relief, 5e-6, 1.5 * active), "pinion.root_relief_length");
  fails(relief(ModificationKind::tip_relief, -1e-6), "pinion.tip_relief");
  fails(relief(ModificationKind::profile_crowning, g.tooth.tip_thickness),
        "pinion.profile_crowning");
  // The scene checks before gmsh runs, naming the wheel's parameter for the wheel.
  GearPairSceneSpec spec;
  spec.wheel_modifications.all_teeth = {relief(ModificationKind::tip_relief, 3e-3)};
  EXPECT_THROW(check_tooth_modifications(spec), InputError);
}
} // namespace

// A rounded tip edge (InvoluteToothSpec::tip_rounding_radius) under tip relief: the flank ends
// at d_Fa, so the relief is measured from there (FlankRollRange::tip) and removes C_a at the
// junction; the arc and its end on the tip circle move by that C_a along the junction's normal
// (the outline stays closed: the junction joins the relieved flank, 1e-15 m being rounding).
TEST(ToothModification, TipRoundingMovesWithTheRelievedFlank)
{
  GearPairSceneSpec spec;
  spec.pair.pinion.tip_rounding_radius = 0.5e-3;
  spec.pair.wheel.tip_rounding_radius = 0.5e-3;
  const Gear g = pinion(spec);
  const double rb = g.tooth.base_radius;
  EXPECT_NEAR(g.range.tip, std::sqrt(g.tooth.tip_form_radius * g.tooth.tip_form_radius - rb * rb),
              1e-15);
  EXPECT_NEAR(g.range.active_tip, g.range.tip, 1e-12); // E lies on the pinion's d_Fa
  const double c = 10e-6;
  const ToothProfile modified = modified_tooth(
      g.tooth, {relief(ModificationKind::tip_relief, c, 1e-3)}, g.range, 1, "pinion");
  ASSERT_EQ(modified.points.size(), g.tooth.points.size() + 2); // the relief starts on each side
  std::size_t arc_points = 0;
  for (std::size_t i = 0, k = 0; i < modified.points.size(); ++i)
  {
    const ProfilePoint& p = modified.points[i];
    if (p.segment != ProfileSegment::tip_round)
      continue;
    // the same nominal point: the arc comes before any inserted kink on the +y side, after
    // both on the −y side
    while (g.tooth.points[k].segment != ProfileSegment::tip_round)
      ++k;
    const Eigen::Vector2d moved = g.tooth.points[k].position - p.position;
    EXPECT_NEAR(moved.norm(), c, 1e-12);
    ++k;
    ++arc_points;
    const bool junction = (i + 1 < modified.points.size() &&
                           modified.points[i + 1].segment == ProfileSegment::relief) ||
                          (i > 0 && modified.points[i - 1].segment == ProfileSegment::relief);
    if (junction) // the relieved flank's own point at d_Fa lies there
    {
      EXPECT_NEAR(removed_depth({relief(ModificationKind::tip_relief, c, 1e-3)}, g.range,
                                std::sqrt(g.tooth.points[k - 1].position.squaredNorm() - rb * rb),
                                true),
                  c, 1e-15);
    }
  }
  EXPECT_EQ(arc_points, 2 * (ProfileResolution().rounding_points - 1));
}

// The fillet takes its flank's removal at the form circle (tooth_modification.cc, FilletBlend):
// a modification that removes material there (root relief: its whole amount; profile crowning:
// the parabola beyond the active profile; a negative slope: more than its amount) left the
// flank's first point δ_f inside the fillet's last one, a step the outline's spline made a notch
// whose root stress grew with the mesh refinement (the invariants' case 15 of seed 20261201: a
// ring's 124 MPa on the rolling mesh, 85 on a mesh per position). On the built-in pinion and a
// ring z 69, both sides: the fillet's root end stays put, every fillet point moves inwards by
// at most δ_f, and from point to point along the fillet and into the form point the outline
// moves by at most 0.15·δ_f more than a parallel offset of the nominal outline by δ_f does (δ_f
// times the turn of its normals: the ring's nominal outline turns by 0.105 rad into its form
// point). Measured 2026-12-07: 0.031·δ_f at most; 0.984·δ_f with the blend switched off.
// The ring z 69 of the planet–ring pair (tests/kinematics/planet_ring_pair.h).
Gear ring()
{
  GearPairSceneSpec spec;
  test_support::make_planet_ring(spec.pair);
  return gear(spec, true);
}

// The indices of a side's fillet points, from its root end, and of the form point after them.
std::vector<std::size_t> fillet_and_form(const std::vector<ProfilePoint>& points, int side)
{
  std::vector<std::size_t> fillet;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].segment == ProfileSegment::fillet && points[i].side == side)
      fillet.push_back(i);
  if (fillet.empty())
    return fillet;
  if (side > 0) // the +y side runs from the tip to the root
    std::reverse(fillet.begin(), fillet.end());
  fillet.push_back(side > 0 ? fillet.back() - 1 : fillet.back() + 1);
  return fillet;
}

TEST(ToothModification, FilletCarriesTheFlankRemoval)
{
  ToothModification crowning, slope;
  crowning.kind = ModificationKind::profile_crowning;
  crowning.amount = 8e-6;
  slope.kind = ModificationKind::profile_slope;
  slope.amount = -10e-6;
  const std::vector<std::pair<std::string, std::vector<ToothModification>>> cases = {
      {"linear root relief", {relief(ModificationKind::root_relief, 15e-6)}},
      {"parabolic root relief",
       {relief(ModificationKind::root_relief, 15e-6, 0.5e-3, ReliefShape::parabolic)}},
      {"profile crowning", {crowning}},
      {"negative slope", {slope}},
      {"crowning, slope, tip relief",
       {crowning, slope, relief(ModificationKind::tip_relief, 10e-6)}}};
  double largest_jump = 0.;
  for (const Gear& g : {pinion(), ring()})
    for (const auto& [name, modifications] : cases)
    {
      SCOPED_TRACE(std::string(g.tooth.internal ? "ring, " : "pinion, ") + name);
      const ToothProfile modified = modified_tooth(g.tooth, modifications, g.range, 1, "gear");
      for (const int side : {-1, 1})
      {
        const std::vector<std::size_t> m = fillet_and_form(modified.points, side);
        const std::vector<std::size_t> n = fillet_and_form(g.tooth.points, side);
        ASSERT_EQ(m.size(), n.size());
        ASSERT_GE(m.size(), 3u);
        const ProfilePoint& form = g.tooth.points[n.back()];
        const double form_depth = removed_depth(
            modifications, g.range,
            std::sqrt(form.position.squaredNorm() - std::pow(g.tooth.base_radius, 2)), side == 1);
        ASSERT_GT(form_depth, 1e-6);
        const auto moved = [&](std::size_t j) -> Eigen::Vector2d
        { return g.tooth.points[n[j]].position - modified.points[m[j]].position; };
        EXPECT_LE(moved(0).norm(), 1e-15); // the fillet's root end
        for (std::size_t j = 0; j + 1 < m.size(); ++j)
        {
          const double depth = moved(j).dot(g.tooth.points[n[j]].normal);
          EXPECT_GE(depth, -1e-15);
          EXPECT_LE(depth, form_depth * (1. + 1e-12));
        }
        for (std::size_t j = 1; j < m.size(); ++j)
        {
          // Offsetting the nominal outline's own turn between two points opens δ·|Δn|.
          const double turn =
              (g.tooth.points[n[j]].normal - g.tooth.points[n[j - 1]].normal).norm();
          largest_jump =
              std::max(largest_jump, (moved(j) - moved(j - 1)).norm() / form_depth - turn);
        }
      }
    }
  EXPECT_LT(largest_jump, 0.15);
  std::printf("largest move between neighbours beyond the offset's: %.3f of δ_f\n", largest_jump);
}

// Where modified flanks touch (touching_point) against closed forms. A removal linear in roll,
// S = s₀ + b·(ρ₁ − ℓ) on the pinion, is a gap s₀ + βx + x²/(2R) across the contact (β = b·r_b1/ρ₁):
// smallest βR before x = 0, at −β²R/2 below s₀. With the slope ending in a kink just behind ℓ
// (S flat below ρ_k) the flanks touch at the kink while βR lies beyond it. A flank that ends
// (its roll range) is not searched past its end. Unmodified (S ≡ 0): the point itself. 1e-13 m,
// 1e-9 m: the search's sampling (its last step is reach/2²⁶).
TEST(ToothModification, TouchingPointClosedForms)
{
  PairFlanks flanks;
  flanks.pinion_base_radius = 30e-3;
  flanks.wheel_base_radius = 60e-3;
  flanks.t2 = 40e-3; // m, T1T2 of an external pair
  flanks.pinion_range.form = flanks.wheel_range.form = 1e-3;
  flanks.pinion_range.tip = flanks.wheel_range.tip = 39e-3;
  flanks.wheel_removal = [](double) { return 0.; };
  const double at = 15e-3, s0 = 5e-6, b = 4e-3; // m, m, -: 4 µm a mm of roll
  const double rho_1 = at, rho_2 = flanks.t2 - at;
  const double radius = rho_1 * rho_2 / (rho_1 + rho_2);
  const double beta = b * flanks.pinion_base_radius / rho_1;

  flanks.pinion_removal = [&](double roll) { return s0 + b * (roll - at); };
  const FlankTouch sloped = touching_point(flanks, at);
  EXPECT_NEAR(sloped.separation, s0 - 0.5 * beta * beta * radius, 1e-13);
  EXPECT_NEAR(sloped.offset, -beta * radius, 1e-9);

  // The kink 10 µm of roll behind ℓ: well inside βR (0.2 mm of roll here).
  const double kink = at - 10e-6;
  flanks.pinion_removal = [&](double roll)
  { return s0 + b * std::max(roll - kink, 0.) - b * 10e-6; };
  const FlankTouch kinked = touching_point(flanks, at);
  const double x_kink = (kink - at) * rho_1 / flanks.pinion_base_radius;
  EXPECT_NEAR(kinked.separation, s0 - b * 10e-6 + x_kink * x_kink / (2. * radius), 1e-13);
  EXPECT_NEAR(kinked.offset, x_kink, 1e-9);

  // The pinion's flank ending 0.1 mm of roll behind ℓ: the search stops there.
  flanks.pinion_removal = [&](double roll) { return s0 + b * (roll - at); };
  flanks.pinion_range.form = at - 0.1e-3;
  const FlankTouch ended = touching_point(flanks, at);
  const double x_end = -0.1e-3 * rho_1 / flanks.pinion_base_radius;
  EXPECT_NEAR(ended.offset, x_end, 1e-9);
  EXPECT_NEAR(ended.separation, s0 + beta * x_end + x_end * x_end / (2. * radius), 1e-13);

  flanks.pinion_removal = [](double) { return 0.; };
  EXPECT_EQ(touching_point(flanks, at).separation, 0.);
  EXPECT_EQ(touching_point(flanks, at).offset, 0.);
}
