// Rolling sweeps (`Stiffness/sweep mesh = once`, stiffness/mesh_stiffness_rolling.cc): one mesh
// per rank, refined along every flank contact of the sweep, factorized once, the bodies turned
// rigidly to each position, against the reference that meshes and factorizes every position
// anew (`per position`). Both are discretizations of the same continuum problem: the small-strain
// stiffness of a body is invariant under a rigid rotation of its own frame, so turning a body
// meshed once changes nothing but the contact pairing, which is made afresh at every position.
// The two differ only by their meshes (a refined band along the flanks against refined discs at
// the predicted contacts of each position), which the tolerances below bound (issue 28's
// accuracy targets: k within 0.3 %, TE within 0.05 µm, load sharing within 0.5 %).
//
// The published load case of docs/references.md §1 (split-path pair, T1 = 49.4 N·m, μ = 0.01),
// default 2D scene, 32 positions over one base pitch, on two MPI ranks (positions over ranks,
// each rank meshes and factorizes once).
#include "stiffness/mesh_stiffness_sweep.h"
#include "tests/stiffness/load_share.h"
#include "tests/stiffness/long_relief.h"
#include "tests/stiffness/planet_ring.h"
#include "tests/stiffness/work_file.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <mpi.h>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
using test_support::share_of;

// The accuracy (k 0.3 %, TE 0.05 µm, load share 0.5 %) at every position of `torque`
// (index into the torque list; the positions when there is none); k_range: the bounds of
// k_once / k_per_position − 1.
void compare_results(const StiffnessSweepResult& reference, const StiffnessSweepResult& rolled,
                     const std::string& name, unsigned int torque,
                     std::pair<double, double> k_range)
{
  const auto& expected =
      reference.by_torque.empty() ? reference.positions : reference.by_torque.at(torque);
  const auto& found = rolled.by_torque.empty() ? rolled.positions : rolled.by_torque.at(torque);
  ASSERT_EQ(found.size(), expected.size());
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  double worst_k = 0., worst_te = 0., worst_share = 0.;
  for (unsigned int i = 0; i < expected.size(); ++i)
  {
    const GearMeshStiffnessResult &a = expected[i], &b = found[i];
    EXPECT_DOUBLE_EQ(a.pinion_torque, b.pinion_torque);
    EXPECT_DOUBLE_EQ(a.pinion_roll_angle, b.pinion_roll_angle);
    const double dk = b.mesh_stiffness / a.mesh_stiffness - 1.;
    const double dte = b.transmission_error - a.transmission_error;
    double dshare = 0.;
    for (const int j : {-1, 0, 1})
      dshare = std::max(dshare, std::abs(share_of(b, j) - share_of(a, j)));
    if (root)
      std::cout << std::setprecision(7) << name << " position " << i << ": k "
                << a.mesh_stiffness / 1e6 << " / " << b.mesh_stiffness / 1e6 << " N/um ("
                << dk * 100 << " %), TE " << a.transmission_error * 1e6 << " / "
                << b.transmission_error * 1e6 << " um, share diff " << dshare << ", iterations "
                << a.active_set_iterations << " / " << b.active_set_iterations << "\n";
    // The unloaded TE is geometry (the modifications' gap at the position): identical by
    // construction, to 1 nm (issue 41: the rolled positions reported the scene's own value).
    EXPECT_NEAR(b.unloaded_transmission_error, a.unloaded_transmission_error, 1e-9)
        << "position " << i;
    // h_c, the tip-edge flag's tolerance: the same setting for both (until 2026-12-03 a rolled
    // position after the first reported 0, and flagged only peaks exactly at A or E).
    EXPECT_DOUBLE_EQ(b.contact_size, a.contact_size) << "position " << i;
    EXPECT_GE(dk, k_range.first) << "position " << i;
    EXPECT_LE(dk, k_range.second) << "position " << i;
    EXPECT_NEAR(dte, 0., 0.05e-6) << "position " << i;
    EXPECT_NEAR(dshare, 0., 5e-3) << "position " << i;
    worst_k = std::max(worst_k, std::abs(dk));
    worst_te = std::max(worst_te, std::abs(dte));
    worst_share = std::max(worst_share, dshare);
  }
  if (root)
    std::cout << name << ": worst |dk| " << worst_k * 100 << " %, |dTE| " << worst_te * 1e6
              << " um, |dshare| " << worst_share << "; per position " << reference.wall_time
              << " s, once " << rolled.wall_time << " s (fixed part " << rolled.once_time
              << " s, per position " << rolled.per_position_time / rolled.positions.size()
              << " s)\n";
}

template <int dim = 2>
void compare_sweeps(const GearMeshStiffnessSettings& settings, const StiffnessSweepSpec& base,
                    const std::string& name, std::pair<double, double> k_range = {-3e-3, 3e-3})
{
  StiffnessSweepSpec spec = base;
  spec.mesh = SweepMesh::per_position;
  const StiffnessSweepResult reference =
      stiffness_sweep<dim>(MPI_COMM_WORLD, settings, spec, stiffness_work_stem(name + "_ref"));
  spec.mesh = SweepMesh::once;
  const StiffnessSweepResult rolled =
      stiffness_sweep<dim>(MPI_COMM_WORLD, settings, spec, stiffness_work_stem(name + "_once"));
  for (unsigned int t = 0; t < std::max<std::size_t>(settings.torques.size(), 1); ++t)
    compare_results(reference, rolled,
                    settings.torques.empty() ? name
                                             : name + " T = " + std::to_string(settings.torques[t]),
                    t, k_range);
}

// The tests' sweeps differ only in their number of positions.
template <int dim = 2>
void compare_sweeps(const GearMeshStiffnessSettings& settings, unsigned int positions,
                    const std::string& name, std::pair<double, double> k_range = {-3e-3, 3e-3})
{
  StiffnessSweepSpec spec;
  spec.positions = positions;
  compare_sweeps<dim>(settings, spec, name, k_range);
}
} // namespace

TEST(SweepOnce, ExternalPairMatchesPerPosition)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  compare_sweeps(settings, 32, "external");
}

// The internal pair of tests/stiffness/planet_ring.h (planet z = 24 in ring z = 69, ring rim of
// 3 modules held on its outer circle) with μ = 0.01: the ring turns with the planet.
TEST(SweepOnce, InternalPairMatchesPerPosition)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "once_internal");
  settings.contact.friction_coefficient = 0.01;
  // 16 positions keep the test's time in bounds (the ring's mesh is the larger one).
  compare_sweeps(settings, 16, "internal");
}

// Modified teeth (issue 41): the scene is meshed with the modified outlines at its own position
// and turned; each rolled position must report its own unloaded TE (the modifications' gap
// there) and the loaded TE built on it. Equal long tip reliefs of 10 µm on both gears (the
// issue's case: once 0.625 µm against 4.375 µm per position for the unloaded TE peak-to-peak
// before the fix), 16 positions.
TEST(SweepOnce, LongTipReliefMatchesPerPosition)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(10e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(10e-6)};
  compare_sweeps(settings, 16, "long tip relief");
}

// Every other profile modification kind at once, on the pinion only or the wheel only: a short
// parabolic tip relief and profile crowning on the pinion, an arc root relief and a profile
// slope on the wheel, 12 positions.
TEST(SweepOnce, ProfileModificationsMatchPerPosition)
{
  using geometry::ModificationKind;
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  geometry::ToothModification tip, crowning, root, slope;
  tip.kind = ModificationKind::tip_relief;
  tip.amount = 8e-6;
  tip.length = 1.5e-3;
  tip.shape = geometry::ReliefShape::parabolic;
  crowning.kind = ModificationKind::profile_crowning;
  crowning.amount = 3e-6;
  root.kind = ModificationKind::root_relief;
  root.amount = 6e-6;
  root.length = 1e-3;
  root.shape = geometry::ReliefShape::arc;
  slope.kind = ModificationKind::profile_slope;
  slope.amount = -4e-6;
  settings.scene.pinion_modifications.all_teeth = {tip, crowning};
  settings.scene.wheel_modifications.all_teeth = {root, slope};
  compare_sweeps(settings, 12, "profile modifications");
}

// The internal pair with a long tip relief on the planet only: a relief on one gear alone.
TEST(SweepOnce, InternalReliefMatchesPerPosition)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "once_internal_relief");
  settings.contact.friction_coefficient = 0.01;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(8e-6)};
  compare_sweeps(settings, 12, "internal relief");
}

// A torque list (issue 27's Harris map) on the rolling sweep: every position starts from the
// first torque and continues to the others, as the per-position sweep does on its own scenes.
TEST(SweepOnce, TorqueListMatchesPerPosition)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  settings.torques = {20., 49.4, 80.};
  compare_sweeps(settings, 6, "torques");
}

// 3D (issue 28): the pair of the first test as a Q1 solid of 8 layers over the 24 mm face, at 8
// positions over one base pitch, μ = 0.01, on the coarse contact size of test_lead_modification
// (0.06 mm: each per-position solve ≈ 10 s); the bodies turn about their axes exactly as in 2D
// (the extrusion is along them). TE and load share hold the tolerances (measured
// 2026-11-26: |ΔTE| ≤ 0.030 µm, |Δshare| ≤ 1.0e-3). k: `once` is softer at every position by
// 0.19–0.47 % (2 ranks, the test; regression: measured 2026-11-27 on 1 rank, per position / once
// N/µm: 386.91 / 386.08, 391.17 / 389.54, 390.74 / 389.77, 388.44 / 386.81, 278.11 / 277.57, 284.04
// / 283.44, 287.43 / 286.09, 286.66 / 286.05), and that is the per-position mesh's error, not the
// rolling:
//  - Both are far from the converged k on these Q1 meshes and approach it from above (a
//    conforming displacement model is too stiff; the tooth bends through ~6 Q1 cells of the
//    0.7 mm body size). The once mesh is finer over every meshing tooth (the graded zones of its
//    band of foci along the flanks), hence nearer. Refinement at position 1 (all sizes × 1/√2,
//    × 1/2, scaled_mesh): per position 391.02, 389.29, 387.44 N/µm; 16 layers 390.73 (−0.08 %).
//  - The difference is the in-plane discretisation: the 2D plane-strain Q1 sweep on the same
//    in-plane meshes gives once − per position = −0.22, −0.43, −0.25, −0.43, −0.20, −0.21, −0.47,
//    −0.22 % (the 3D figures to 0.02 %), and the 2D converged k (Q2, sizes × 1/2: 395.63 N/µm at
//    position 1, Q2 × 1 and × 1/√2 within 0.05 %) puts the Q1 k at +1.41 % (per position) and
//    +0.98 % (once) at these sizes; the 3D per-position refinement × 1/2 drops k by 0.92 % (2D
//    Q1: 0.96 %), so the converged 3D k at position 1 is ≈ 387.44 · 395.63 / 397.37 ≈ 385.7
//    N/µm: per position +1.4 %, once +1.0 %.
//  - The difference shrinks with the mesh: all sizes × 1/√2 (446k DoFs once), at the three worst
//    positions −0.42 → −0.08 %, −0.42 → −0.16 %, −0.47 → −0.21 %; in 2D Q1 at sizes × 1/2 every
//    position within 0.17 % (SweepOnce.Q1RefinedMatchesPerPosition).
// So the 0.3 % is met by the converged comparison; here the sign is held (once softer,
// nearer the converged k) with the measured spread: −0.5 % ≤ Δk ≤ 0.
TEST(SweepOnce, ThreeDQ1MatchesPerPosition)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  settings.elasticity.degree = 1;
  settings.scene.mesh.dimension = 3;
  settings.scene.mesh.layers = 8;
  settings.scene.mesh.contact_size = 6e-5; // m
  // Position 4 (18.41°) lies next to the pitch point, where the sliding direction reverses
  // inside the contact zone: the Tresca bounds' fixed point took 32 iterations on the default
  // 3D mesh and more than the default 40 on this one (both sweeps), with no node changing state.
  settings.contact.max_iterations = 150;
  compare_sweeps<3>(settings, 8, "3D Q1", {-5e-3, 0.});
}

// The 3D pair's k difference at its contact size (ThreeDQ1MatchesPerPosition: −0.20 to −0.47 %)
// is the in-plane Q1 discretisation, which this 2D plane-strain Q1 sweep on the same in-plane
// sizes reproduces to 0.02 %; with every size halved (scaled_mesh: contact 0.03 mm, body
// 0.35 mm, rim 1.4 mm, growth 0.175) the two meshes agree within the 0.3 % (regression:
// measured 2026-11-27, −0.03 to −0.16 %, once softer at every position; 52 s on 2 ranks).
TEST(SweepOnce, Q1RefinedMatchesPerPosition)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.01;
  settings.elasticity.degree = 1;
  settings.scene.mesh.contact_size = 6e-5; // m, the 3D test's (the other sizes the default's)
  settings.scene.mesh = scaled_mesh(settings.scene.mesh, 0.5);
  settings.contact.max_iterations = 150;
  compare_sweeps(settings, 8, "2D Q1 refined");
}
