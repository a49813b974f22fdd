// The 3D influence-coefficient model (Stiffness/contact model = influence coefficients with
// Mesh/dimension = 3, docs/ltca.md §3) against the exact 3D FE contact path on the default spur
// pair: issue 47's k within 1 % at every checked position, TE within 0.1 µm, load sharing within
// 1 %. The reference settings and the measured deviations are in the test's comment.
#include "kinematics/automatic_sizes.h"
#include "stiffness/influence_sweep.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "tests/stiffness/load_share.h"
#include "tests/stiffness/long_relief.h"
#include "tests/stiffness/work_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
using test_support::largest_share_difference;

// The exact sweep and the fast one on the same settings, position by position; returns the
// worst |Δk| (-), |ΔTE| (m), |Δshare| (-) and |ΔK_Hβ|/K_Hβ (-).
std::array<double, 4> compare_3d(const GearMeshStiffnessSettings& base, unsigned int positions,
                                 const std::string& name)
{
  StiffnessSweepSpec spec;
  spec.positions = positions;
  spec.mesh = SweepMesh::per_position;
  GearMeshStiffnessSettings settings = base;
  settings.contact.friction_coefficient = 0.; // the fast model is frictionless
  const StiffnessSweepResult exact =
      stiffness_sweep<3>(MPI_COMM_SELF, settings, spec, stiffness_work_stem(name + "_exact"));
  settings.contact_model = ContactModel::influence_coefficients;
  const StiffnessSweepResult fast =
      influence_sweep<3>(MPI_COMM_SELF, settings, spec, stiffness_work_stem(name + "_fast"));
  EXPECT_EQ(fast.positions.size(), exact.positions.size());
  std::array<double, 4> worst{};
  for (std::size_t i = 0; i < exact.positions.size(); ++i)
  {
    const GearMeshStiffnessResult &a = exact.positions[i], &b = fast.positions[i];
    const double dk = b.mesh_stiffness / a.mesh_stiffness - 1.;
    const double dte = b.transmission_error - a.transmission_error;
    const double dshare = largest_share_difference(a, b);
    std::cout << std::setprecision(6) << name << " " << i << ": k " << a.mesh_stiffness / 1e6
              << " / " << b.mesh_stiffness / 1e6 << " N/um (" << dk * 100 << " %), TE "
              << a.transmission_error * 1e6 << " / " << b.transmission_error * 1e6 << " um, share "
              << dshare << ", K_Hbeta " << a.face_load_factor << " / " << b.face_load_factor
              << ", p " << a.max_contact_pressure / 1e6 << " / " << b.max_contact_pressure / 1e6
              << " MPa\n";
    worst[0] = std::max(worst[0], std::abs(dk));
    worst[1] = std::max(worst[1], std::abs(dte));
    worst[2] = std::max(worst[2], dshare);
    worst[3] = std::max(worst[3], std::abs(b.face_load_factor / a.face_load_factor - 1.));
  }
  std::cout << name << ": worst |dk| " << worst[0] * 100 << " %, |dTE| " << worst[1] * 1e6
            << " um, |dshare| " << worst[2] << ", |dK_Hbeta| " << worst[3] * 100 << " %; exact "
            << exact.wall_time << " s (" << exact.positions.front().n_dofs << " DoFs), influence "
            << fast.wall_time << " s (once " << fast.once_time << " s, " << fast.influence.n_dofs
            << " DoFs; contact " << fast.per_position_time << " s)\n";
  return worst;
}

// The 3D scene of these comparisons: Q1 (the FE body at Q2 and 8 layers was 1.56M DoFs, factored
// in 476 s, 13 GB; at Q1 and 4 layers 119k DoFs, 12 s), the exact path's contact size 0.06 mm
// (the fast model sets its own h_f). Lead modifications: test_influence_3d_lead.cc.
GearMeshStiffnessSettings q1_settings(unsigned int layers)
{
  GearMeshStiffnessSettings settings;
  settings.scene.mesh.dimension = 3;
  settings.scene.mesh.layers = layers;
  settings.elasticity.degree = 1;
  settings.scene.mesh.contact_size = 6e-5; // m
  return settings;
}

// Issue 47's k 1 %, TE 0.1 µm, load share 1 %, K_Hβ 2 % on the worst of compare_3d.
void expect_issue_accuracy(const std::array<double, 4>& worst)
{
  EXPECT_LT(worst[0], 0.01);
  EXPECT_LT(worst[1], 0.1e-6);
  EXPECT_LT(worst[2], 0.01);
  EXPECT_LT(worst[3], 0.02);
}
} // namespace

// The exact path per position at h_c = 0.06 mm (Q1, 4 layers, 98k–104k DoFs a position) is the
// reference: affordable (~35 s for the four positions), not converged (+1.0–1.4 % stiff against
// its Richardson limit at 8 layers, bench/contact_speed.md session 12), so this checks the fast
// model against the exact path on a comparable discretisation. Regression: measured 2026-12-02
// with the unknowns on the node planes, the rim coarse beyond the modelled teeth and the flank
// band at 1.5·h_f (ltca47g: 41.4k body DoFs, was 119k), worst |Δk| 0.57 % (position 1, double
// contact; 0.39 % on the body graded by depth only, 0.51 % with the coarse rim alone), |ΔTE|
// 0.029 µm, |Δshare| 0.0017, |ΔK_Hβ| 1.02 % (fast 1.020–1.027 against exact 1.009–1.018; with
// the unknowns on the layers' middles it was +1.9 … +2.2 %, docs/ltca.md §3). With the end
// faces' plane-stress layer (ltca47k, 2026-12-03, one unlocked run): k +0.12, +0.16, −0.28,
// −0.14 %, |ΔTE| 0.020 µm, |Δshare| 0.0019, K_Hβ −0.45, −0.52, +0.25, +0.44 % (fast 1.012–1.014
// against exact 1.009–1.018). With the end faces' layer from the quarter-space
// (end_face_layer_excess, 2026-12-05, one run): k +0.29, +0.35, +0.03, +0.18 %, |ΔTE| 0.018 µm,
// K_Hβ +0.52, +0.49, +0.54, +0.55 %. With the layer kernel between the planes (own-plane loads,
// 2026-12-07, one run; each plane's own line load): worst |Δk| 0.25 %, |ΔTE| 0.013 µm,
// |Δshare| 0.0016, |ΔK_Hβ| 0.52 %. Tolerances: the issue's 1 %, 0.1 µm, 1 %, 2 % (≈ 1.8×, 3×, 5×,
// 2× the worst measured before the end faces, the looser of the two).
TEST(InfluenceCoefficients3D, DefaultSpurAgainstExact)
{
  expect_issue_accuracy(compare_3d(q1_settings(4), 4, "influence_3d"));
}

// Profile modifications in 3D: the same reference with a 10 µm long tip relief on both gears
// (each node plane's pair touching where its modified flanks' gap is smallest, docs/ltca.md §5).
// Measured 2026-12-05 (one run): k −0.10, −0.05, −0.11, −0.20 %, |ΔTE| 0.014 µm, |Δshare|
// 0.0066, K_Hβ within 0.42 %; with the layer kernel (2026-12-07): k within 0.044 %,
// |ΔTE| 0.003 µm, |Δshare| 0.0060, K_Hβ within 0.55 %; tolerances the issue's 1 %, 0.1 µm, 1 %,
// 2 % (≈ 5×, 7×, 1.5×, 4× the worst measured).
TEST(InfluenceCoefficients3D, TipReliefAgainstExact)
{
  GearMeshStiffnessSettings settings = q1_settings(4);
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(10e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(10e-6)};
  expect_issue_accuracy(compare_3d(settings, 4, "influence_3d_relief"));
}

// A helical pair's sharp tip edge on a modified flank (docs/ltca.md §3 "On the same node planes"):
// the small helical pair of tests/helical (z 19/29, m_n 2 mm, β ±10°, b 8 mm, 20 N·m) with 6 µm
// long tip reliefs on both gears, the fast model on 20 layers (Q1, μ 0, body 0.75 mm, rim 2.5 mm),
// 4 positions. At 0.625 pair +1's line leaves the path at A near z = 1.8 mm, so the planes beyond
// carry the wheel's relieved tip edge. The reference: the exact path's K_Hβ on the same 20 node
// planes (regression: measured 2026-12-06, the exact per-position sweep of
// `influence_helical.py small-tip-relief` with Mesh/layers=20 on 2 ranks, gearstiff of main
// f0e1afa, one run, 185 s): 1.0681, 1.0606, 1.1492, 1.0282. The fast model gave 1.0537, 1.0602,
// 1.2062, 1.0180 with a strip under the edge (+5.0 % at 0.625: the edge's plane 38.5 N/mm against
// the exact 27.0), 1.0537, 1.0602, 1.1459, 1.0180 with its corner's near field (−1.35, −0.04,
// −0.29, −0.99 %). Tolerance the issue's 2 % (≈ 1.5× the worst measured, 0.4× the defect).
TEST(InfluenceCoefficients3D, HelicalRelievedTipEdgeFaceLoad)
{
  GearMeshStiffnessSettings settings = q1_settings(20);
  kinematics::GearPairSpec& pair = settings.scene.pair;
  pair = kinematics::split_path_pair();
  for (kinematics::GearSpec* gear : {&pair.pinion, &pair.wheel})
  {
    gear->normal_module = 2e-3;
    gear->profile_shift = 0.;
    gear->face_width = 8e-3;
  }
  pair.pinion.teeth = 19;
  pair.wheel.teeth = 29;
  pair.pinion.helix_angle = 10. * M_PI / 180.;
  pair.wheel.helix_angle = -10. * M_PI / 180.;
  std::vector<kinematics::DerivedSize> derived;
  kinematics::resolve_automatic_sizes(pair, {true, true, true, true}, 0., derived);
  settings.scene.mesh.body_size = 0.75e-3; // m
  settings.scene.mesh.rim_size = 2.5e-3;   // m
  settings.pinion_torque = 20.;            // N·m
  settings.contact.friction_coefficient = 0.;
  settings.contact_model = ContactModel::influence_coefficients;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(6e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(6e-6)};
  StiffnessSweepSpec spec;
  spec.positions = 4;
  const StiffnessSweepResult fast = influence_sweep<3>(
      MPI_COMM_SELF, settings, spec, stiffness_work_stem("influence_3d_helical_edge"));
  const std::array<double, 4> exact = {{1.0681, 1.0606, 1.1492, 1.0282}};
  ASSERT_EQ(fast.positions.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
  {
    const GearMeshStiffnessResult& r = fast.positions[i];
    std::cout << std::setprecision(6) << "position " << i << ": roll "
              << r.pinion_roll_angle * 180. / M_PI << " deg, k " << r.mesh_stiffness / 1e6
              << " N/um, K_Hbeta " << r.face_load_factor << " (exact " << exact[i] << ", "
              << (r.face_load_factor / exact[i] - 1.) * 100. << " %)\n";
    EXPECT_NEAR(r.face_load_factor / exact[i], 1., 0.02) << "position " << i;
  }
}
