// Mesh stiffness of the split-path pair (docs/references.md §1, Reszuta & Drewniak
// 2015) from the frictional FE contact solve of stiffness/mesh_stiffness.h under the published load
// case (T1 = 49.4 N·m on the pinion, pinion bore free only to rotate, wheel bore fixed, μ = 0.01),
// against the stiffness the paper's ANSYS model reported, k'_j = 327.2·10⁶ N/m (single pair) and
// k'_d = 497.5·10⁶ N/m (double pair), with ISO 6336-1 c'·b (kinematics/iso_stiffness.h) beside
// it and a refinement study whose Richardson estimate gives the discretization error.
//
// The model here is stated, not tuned: 2D plane strain (and plane stress), Q2 elements, the
// common face width 24 mm as thickness, E = 210 GPa, ν = 0.3 (not published), the default bores of
// kinematics::split_path_pair() (pinion 20 mm, wheel 40 mm diameter: not published), rigid hubs,
// full rims with three teeth per gear (stiffness::default_stiffness_scene()).
#include "errors/errors.h"
#include "kinematics/iso_stiffness.h"
#include "stiffness/mesh_stiffness.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "tests/stiffness/work_file.h"

#include <cmath>
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
namespace ansys = gearstiff::kinematics::split_path_published; // the published FE values

GearMeshStiffnessSettings published_case(const std::string& position)
{
  GearMeshStiffnessSettings settings;
  settings.scene.position = geometry::parse_pair_position(position, "position");
  settings.contact.friction_coefficient = 0.01; // docs/references.md §1
  settings.scene_file = stiffness_work_stem(position) + ".msh";
  return settings;
}

GearMeshStiffnessResult solve(const GearMeshStiffnessSettings& settings)
{
  GearMeshStiffness<2> analysis(MPI_COMM_SELF, settings);
  const GearMeshStiffnessResult r = analysis.run();
  std::filesystem::remove(settings.scene_file);
  std::cout << std::setprecision(5) << settings.scene_file << ", "
            << fem::to_string(settings.elasticity.model) << ", h_c = " << r.contact_size * 1e3
            << " mm: k = " << r.mesh_stiffness / 1e6 << " N/um, dphi = " << r.pinion_rotation
            << " rad, loaded pairs " << r.loaded_pairs << ", |Tw/T1| = " << r.torque_ratio
            << ", p_max = " << r.max_contact_pressure / 1e6 << " MPa, root stress "
            << r.pinion_root_stress / 1e6 << "/" << r.wheel_root_stress / 1e6 << " MPa, "
            << r.n_dofs << " DoFs, " << r.active_set_iterations << " iterations, " << r.total_time
            << " s\n";
  return r;
}

// The solves are shared by the tests below (each costs seconds).
struct Study
{
  std::vector<RefinementLevel> linear_levels; // Q1, single pair, plane strain, sizes × √2, 1, 1/√2
  RichardsonEstimate linear_estimate;
  GearMeshStiffnessResult single_strain, single_stress, double_strain; // published case, μ 0.01
  GearMeshStiffnessResult frictionless, frictionless_refined;          // Q2, default and √2 finer
};

const Study& study()
{
  static const Study result = []
  {
    Study s;
    GearMeshStiffnessSettings settings = published_case("single");
    const geometry::SceneMeshSettings base = settings.scene.mesh;
    // The refinement study is frictionless: μ = 0.01 changes k by 0.01% (measured), and its
    // fixed point adds active-set iterations (9 solves instead of 5 at the default mesh).
    settings.contact.friction_coefficient = 0.;
    // Q1 on the default size field, √2 coarser and √2 finer (the coarsest that still meshes the
    // single-pair scene with quadrilaterals; finer Q1 levels leave the asymptotic range, see
    // docs/accuracy.md): a Richardson estimate independent of the Q2 default.
    settings.elasticity.degree = 1;
    for (const double factor : {std::sqrt(2.), 1., 1. / std::sqrt(2.)})
    {
      settings.scene.mesh = scaled_mesh(base, factor);
      const GearMeshStiffnessResult r = solve(settings);
      s.linear_levels.push_back({factor, r.mesh_stiffness, r.n_dofs, r.total_time});
    }
    s.linear_estimate = richardson_estimate(s.linear_levels);
    settings.elasticity = default_stiffness_elasticity();
    settings.scene.mesh = base;
    s.frictionless = solve(settings);
    settings.scene.mesh = scaled_mesh(base, 1. / std::sqrt(2.));
    s.frictionless_refined = solve(settings);
    settings = published_case("single");
    s.single_strain = solve(settings);
    settings.elasticity.model = fem::PlanarModel::plane_stress;
    s.single_stress = solve(settings);
    s.double_strain = solve(published_case("double"));
    const double k = s.frictionless.mesh_stiffness;
    std::cout << "Richardson (Q1, single, plane strain): k = "
              << s.linear_estimate.extrapolated / 1e6 << " N/um, observed order "
              << s.linear_estimate.observed_order << "; Q2 default " << k / 1e6 << " N/um ("
              << (k / s.linear_estimate.extrapolated - 1) * 100 << " % from it, "
              << (k / s.frictionless_refined.mesh_stiffness - 1) * 100
              << " % from Q2 refined by sqrt 2)\n"
              << "against ANSYS: single plane strain "
              << (s.single_strain.mesh_stiffness / ansys::single_pair_stiffness - 1) * 100
              << " %, plane stress "
              << (s.single_stress.mesh_stiffness / ansys::single_pair_stiffness - 1) * 100
              << " %; double plane strain "
              << (s.double_strain.mesh_stiffness / ansys::double_pair_stiffness - 1) * 100
              << " %\n";
    return s;
  }();
  return result;
}
} // namespace

TEST(MeshStiffness, RefinementStudyOfTheDefaultScene)
{
  const Study& s = study();
  // Q1: monotone convergence from above (a displacement method is too stiff on coarse meshes).
  // The rate is below the asymptotic O(h²) of the energy (measured 0.9): these levels resolve the
  // Hertz half-width (a ≈ 0.08 mm) with only 2-4 cells and are unstructured, not nested, so a
  // wide band rather than a value.
  EXPECT_GT(s.linear_levels[0].stiffness, s.linear_levels[1].stiffness);
  EXPECT_GT(s.linear_levels[1].stiffness, s.linear_levels[2].stiffness);
  EXPECT_GT(s.linear_estimate.observed_order, 0.5);
  EXPECT_LT(s.linear_estimate.observed_order, 3.);
  // The Q2 default against the Q1 extrapolation (measured 2026-11-26: −0.36 %; the extrapolation
  // itself carries ~0.5 %, docs/accuracy.md: tolerance 1 %) and against Q2 on a √2 finer field
  // (measured −0.021 %; tolerance 0.07 %, about three times that).
  const double k = s.frictionless.mesh_stiffness;
  EXPECT_NEAR(k / s.linear_estimate.extrapolated, 1., 0.01);
  EXPECT_NEAR(k / s.frictionless_refined.mesh_stiffness, 1., 7e-4);
  // Friction μ = 0.01 barely moves the stiffness (no sliding at the pitch point).
  EXPECT_NEAR(s.single_strain.mesh_stiffness / k, 1., 1e-3);
}

TEST(MeshStiffness, SplitPathAgainstAnsys)
{
  const Study& s = study();
  EXPECT_EQ(s.single_strain.loaded_pairs, 1u);
  EXPECT_EQ(s.double_strain.loaded_pairs, 2u);
  // The tolerance is the modelling difference, not the discretization (< 1%, test above):
  //  - docs/references.md §1: an independent plane-strain model with this 10 mm pinion bore
  //    radius came ~10% below ANSYS; the bore is not published, and 10 → 15 mm raised the
  //    single-pair value by ~7% (double ~10%), so the ANSYS bore alone can explain several
  //    percent either way;
  //  - ANSYS was 3D with a 26 mm pinion on a 24 mm wheel, this model is 2D with 24 mm throughout;
  //  - the support: rigid hubs here, bore nodes fixed radially but free tangentially in ANSYS;
  //  - E and ν are not published (210 GPa, 0.3 assumed: k scales with E).
  // Hence the converged single-pair value is expected at 0.90 ± 0.05 of ANSYS (measured 0.861).
  EXPECT_NEAR(s.single_strain.mesh_stiffness / ansys::single_pair_stiffness, 0.90, 0.05);
  // Plane stress lowers the bulk stiffness by about (1 − ν²) = 0.91 against plane strain, so
  // 0.90·0.91 ≈ 0.82 ± 0.05 (measured 0.81); the 3D value lies between the two planar ones.
  EXPECT_NEAR(s.single_stress.mesh_stiffness / ansys::single_pair_stiffness, 0.82, 0.05);
  EXPECT_LT(s.single_stress.mesh_stiffness, s.single_strain.mesh_stiffness);
  // The double pair is more sensitive to the bore (10% against 7% per 5 mm, docs/references.md §1),
  // so with the same small bore it sits further below ANSYS than the single pair does. Its ratio
  // itself has no independent value (the ANSYS bore and the position within the double zone are
  // not published): regression, measured 2026-11-26 (0.7967; deterministic, tolerance 1e-3).
  const double single_ratio = s.single_strain.mesh_stiffness / ansys::single_pair_stiffness;
  const double double_ratio = s.double_strain.mesh_stiffness / ansys::double_pair_stiffness;
  EXPECT_LT(double_ratio, single_ratio);
  EXPECT_NEAR(double_ratio, 0.7967, 1e-3);
}

TEST(MeshStiffness, IsoStiffnessBesideTheFeValue)
{
  const kinematics::GearPairGeometry pair =
      kinematics::compute_gear_pair(kinematics::split_path_pair());
  const kinematics::IsoStiffness iso = kinematics::iso_mesh_stiffness(pair);
  const Study& s = study();
  std::cout << "ISO 6336-1 c'b = " << iso.single_per_width / 1e6 << " N/um; FE single pair "
            << (s.single_strain.mesh_stiffness / iso.single_per_width - 1) * 100
            << " % from it; ISO c_gamma_alpha b = " << iso.mesh_alpha_per_width / 1e6 << " N/um\n";
  // docs/references.md §5: c'·b ≈ 330 N/µm for this pair (the value is rounded: 3%).
  EXPECT_NEAR(iso.single_per_width, 330e6, 0.03 * 330e6);
  // Method B is an empirical fit (q' polynomial of solid steel gears, times C_M = 0.8 for the
  // measured-to-theoretical ratio), printed beside the FE value, not an oracle: the ratio has no
  // independent value. Regression: measured 2026-11-26 (0.8748, −12.5 %; tolerance 1e-3).
  EXPECT_NEAR(s.single_strain.mesh_stiffness / iso.single_per_width, 0.8748, 1e-3);
}
