// The 3D influence-coefficient model with lead modifications (docs/ltca.md §3 "Lead
// modifications") against the exact 3D FE contact path on the default spur pair: issue 47's k
// within 1 % at every checked position, TE within 0.1 µm, K_Hβ within 2 %. The exact path at 16
// layers takes ~2 min a case, so its values are stored here with the settings of their run; the
// fast model runs at the same 16 layers (the fewest it accepts with lead modifications).
//
// And, by hand (--gtest_also_run_disabled_tests), the ladder that set the 16 layers: either model
// on any layers, contact and body size, crowning and slope (environment variables below).
#include "stiffness/influence_sweep.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "tests/stiffness/planet_ring.h"
#include "tests/stiffness/work_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
// What one position of the exact path reported (N/µm, µm, -).
struct StoredPosition
{
  double stiffness = 0.;          // N/µm
  double transmission_error = 0.; // µm
  double face_load_factor = 0.;   // -, K_Hβ
};

// The default pair in 3D, Q1, 4 sweep positions, frictionless (the fast model is), `crowning` and
// `slope` (m) of lead modification on the pinion's flanks; `body_size` (m) 1 mm instead of the
// default 0.7 mm so that 16 layers fit the exact path's cell limit (2e5 hexahedra,
// errors/limits.h).
GearMeshStiffnessSettings lead_settings(unsigned int layers, double crowning, double slope,
                                        double contact_size, double body_size)
{
  GearMeshStiffnessSettings settings;
  settings.scene.mesh.dimension = 3;
  settings.scene.mesh.layers = layers;
  settings.elasticity.degree = 1;
  settings.scene.mesh.contact_size = contact_size;
  if (body_size > 0.)
    settings.scene.mesh.body_size = body_size;
  settings.scene.pinion_modifications.lead.crowning = crowning;
  settings.scene.pinion_modifications.lead.slope = slope;
  settings.contact.friction_coefficient = 0.;
  return settings;
}

StiffnessSweepSpec four_positions()
{
  StiffnessSweepSpec spec;
  spec.positions = 4;
  spec.mesh = SweepMesh::per_position;
  return spec;
}

StiffnessSweepResult fast_sweep(GearMeshStiffnessSettings settings, const std::string& name)
{
  settings.contact_model = ContactModel::influence_coefficients;
  return influence_sweep<3>(MPI_COMM_SELF, settings, four_positions(), stiffness_work_stem(name));
}

// The fast model at 16 layers against the stored exact values, position by position, at issue
// 47's k 1 %, TE 0.1 µm, K_Hβ 2 %.
void expect_against_stored(const StiffnessSweepResult& fast,
                           const std::array<StoredPosition, 4>& exact, const std::string& name)
{
  ASSERT_EQ(fast.positions.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
  {
    const GearMeshStiffnessResult& b = fast.positions[i];
    const double dk = b.mesh_stiffness / 1e6 / exact[i].stiffness - 1.;
    const double dte = b.transmission_error * 1e6 - exact[i].transmission_error;
    const double dk_hb = b.face_load_factor / exact[i].face_load_factor - 1.;
    std::cout << std::setprecision(6) << name << " " << i << ": k " << exact[i].stiffness << " / "
              << b.mesh_stiffness / 1e6 << " N/um (" << dk * 100 << " %), TE "
              << exact[i].transmission_error << " / " << b.transmission_error * 1e6
              << " um, K_Hbeta " << exact[i].face_load_factor << " / " << b.face_load_factor << " ("
              << dk_hb * 100 << " %)\n";
    EXPECT_LT(std::abs(dk), 0.01) << "position " << i;
    EXPECT_LT(std::abs(dte), 0.1) << "position " << i;
    EXPECT_LT(std::abs(dk_hb), 0.02) << "position " << i;
  }
  std::cout << name << ": influence " << fast.wall_time << " s (" << fast.influence.n_dofs
            << " body DoFs)\n";
}
} // namespace

// The exact path (Stiffness/contact model = finite element, per position) on the default pair
// with lead crowning on the pinion, Q1, 4 positions, μ 0, h_c 0.06 mm; regression: measured
// 2026-12-02 (ltca47h, DISABLED_Ladder, one run each, ~3.8 GB at 16 layers, 5.8 GB at 24). The
// body size (1 mm at 16 layers, 1.2 mm at 24 instead of 0.7) is what lets the exact path fit its
// cell limit; at 8 layers 0.7 → 1 mm moved the exact k by −0.00, +0.10, +0.10, +0.21 %.
// C_β = 10 µm, 16 layers, body 1 mm (290k DoFs a position, 143 s).
constexpr std::array<StoredPosition, 4> exact_crowning_10um = {{{262.1288, 7.640065, 2.295985},
                                                                {262.7423, 7.622225, 2.304280},
                                                                {198.8855, 10.06952, 1.872290},
                                                                {202.1144, 9.908653, 1.892672}}};
// C_β = 20 µm, 24 layers, body 1.2 mm (379k DoFs a position, 237 s): the exact path is not
// converged along the face at 16 layers with a crowned contact (16 → 24 layers: k +0.3 …
// +0.6 %), so this is the finest reference run.
constexpr std::array<StoredPosition, 4> exact_crowning_20um = {{{230.3561, 8.693848, 3.100191},
                                                                {230.9873, 8.670092, 3.107371},
                                                                {171.7056, 11.66346, 2.476320},
                                                                {174.5612, 11.47266, 2.507880}}};

// The fast model at 16 layers (body 1 mm: the default 0.7 mm exceeds the cell estimate at 16
// layers, which does not yet count the fast body's coarse rim; at 8 layers 0.7 → 1 mm moved its k
// by ≤ 0.05 %). Measured 2026-12-02 (ltca47h): C_β 10 µm k +0.41, +0.37, +0.23, +0.23 %, TE
// −0.031 … −0.023 µm, K_Hβ +0.76, +0.66, +0.09, +0.12 %; C_β 20 µm k +0.50, +0.50, +0.24,
// +0.32 %, TE −0.044 … −0.028 µm, K_Hβ +0.32, +0.39, +0.19, +0.03 %. Tolerances: the issue's
// 1 %, 0.1 µm, 2 % (≈ 2×, 2.3×, 2.6× the worst measured).
TEST(InfluenceCoefficients3DLead, LeadCrowningSixteenLayers)
{
  expect_against_stored(fast_sweep(lead_settings(16, 10e-6, 0., 6e-5, 1e-3), "lead_crowning_10"),
                        exact_crowning_10um, "crowning 10 um");
  expect_against_stored(fast_sweep(lead_settings(16, 20e-6, 0., 6e-5, 1e-3), "lead_crowning_20"),
                        exact_crowning_20um, "crowning 20 um");
}

// The ladder behind the 16 layers, by hand: LADDER_FAST=1 runs the fast model (else the exact
// path), LADDER_LAYERS (8), LADDER_HC (m, 6e-5), LADDER_BODY (m, 0: the default 0.7 mm),
// LADDER_CROWN (m, 10e-6), LADDER_SLOPE (m, 0) on the pinion, LADDER_INTERNAL; prints k, TE, K_Hβ,
// p_max of the four positions. Run from the build folder with GEARSTIFF_BINARY_DIR set.
TEST(InfluenceCoefficients3DLead, DISABLED_Ladder)
{
  const auto env = [](const char* name, double fallback)
  {
    const char* value = std::getenv(name);
    return value ? std::atof(value) : fallback;
  };
  GearMeshStiffnessSettings settings =
      lead_settings(static_cast<unsigned int>(env("LADDER_LAYERS", 8)), env("LADDER_CROWN", 10e-6),
                    env("LADDER_SLOPE", 0.), env("LADDER_HC", 6e-5), env("LADDER_BODY", 0.));
  // LADDER_INTERNAL=1: the planet-ring pair of the 2D tests (rim 3·m_n) instead of the default
  // pair; the 3D model refuses it, so this needs the refusal lifted by hand.
  if (env("LADDER_INTERNAL", 0.) > 0.)
  {
    settings.scene.pair = planet_ring_pair();
    settings.scene.wheel_rim_thickness = 3. * 2.5e-3;
  }
  const bool fast = env("LADDER_FAST", 0.) > 0.;
  const StiffnessSweepResult result =
      fast ? fast_sweep(settings, "ladder_fast")
           : stiffness_sweep<3>(MPI_COMM_SELF, settings, four_positions(),
                                stiffness_work_stem("ladder_exact"));
  for (std::size_t i = 0; i < result.positions.size(); ++i)
  {
    const GearMeshStiffnessResult& r = result.positions[i];
    std::cout << std::setprecision(7) << (fast ? "fast " : "exact ") << i << ": k "
              << r.mesh_stiffness / 1e6 << " N/um, TE " << r.transmission_error * 1e6
              << " um, K_Hbeta " << r.face_load_factor << ", p " << r.max_contact_pressure / 1e6
              << " MPa, " << r.n_dofs << " DoFs\n";
  }
  std::cout << "wall " << result.wall_time << " s, body DoFs " << result.influence.n_dofs << "\n";
}
