// Lead modifications in 3D (issue 27): the load across the face width (stiffness/face_load.h)
// of the split-path pair of docs/references.md §1 at its single-contact position, on a coarse
// extruded mesh (Q1, 8 layers; each test ≈ 20 s). The unmodified 3D solve against the 2D
// plane-strain and plane-stress solves on the same transverse mesh; symmetric lead crowning puts
// the peak line load in the middle of the face, symmetric about it, with K_Hβ > 1; a lead slope
// moves the load to the end it does not relieve. Zero lead modifications write today's mesh byte
// for byte (tests/geometry/test_tooth_modification_lead.cc), so their solve is today's.
#include "stiffness/face_load.h"
#include "stiffness/mesh_stiffness.h"
#include "tests/stiffness/work_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <vector>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
GearMeshStiffnessSettings coarse_3d(const std::string& name)
{
  GearMeshStiffnessSettings settings;
  settings.elasticity.degree = 1;          // Q1 on a coarse contact zone keeps a solve near 10 s
  settings.scene.mesh.contact_size = 6e-5; // m (as test_stiffness_sweep's 3D case)
  settings.scene.mesh.layers = 8;
  settings.scene.mesh.dimension = 3;
  settings.scene_file = stiffness_work_stem(name) + ".msh";
  return settings;
}

template <int dim>
GearMeshStiffnessResult solve(const GearMeshStiffnessSettings& settings)
{
  GearMeshStiffness<dim> analysis(MPI_COMM_SELF, settings);
  const GearMeshStiffnessResult result = analysis.run();
  std::filesystem::remove(settings.scene_file);
  return result;
}

double face_width()
{
  return kinematics::compute_gear_pair(GearMeshStiffnessSettings().scene.pair).common_face_width;
}

void print(const std::string& label, const GearMeshStiffnessResult& r, const FaceLoadSummary& s)
{
  std::cout << std::setprecision(6) << label << ": k " << r.mesh_stiffness / 1e6 << " N/um, TE "
            << r.transmission_error * 1e6 << " um, K_Hbeta " << s.factor << ", peak at z "
            << s.peak_z * 1e3 << " mm, force from pressures " << s.force << " N (pairs "
            << r.pairs.front().normal_force << " N), " << r.total_time << " s\n  w(z) [N/mm]:";
  for (std::size_t i = 0; i < s.z.size(); ++i)
    std::cout << " " << s.z[i] * 1e3 << ":" << s.line_load[i] * 1e-3;
  std::cout << "\n";
}

double summed_normal_force(const GearMeshStiffnessResult& r)
{
  double total = 0.;
  for (const auto& p : r.pairs)
    total += std::max(p.normal_force, 0.);
  return total;
}

// The face load of the coarse 3D pair (work files `name`) with `lead` on the pinion, printed
// under `label`.
FaceLoadSummary pinion_lead_face_load(const std::string& name,
                                      const geometry::LeadModification& lead,
                                      const std::string& label)
{
  GearMeshStiffnessSettings settings = coarse_3d(name);
  settings.scene.pinion_modifications.lead = lead;
  const GearMeshStiffnessResult r = solve<3>(settings);
  const FaceLoadSummary s = summarise_face_load(r.face_load);
  print(label, r, s);
  return s;
}
} // namespace

// 2D against 3D without lead modifications. Without friction the contact solve minimises the
// potential energy; plane strain is the 3D solution restricted to u_z = 0 on the extruded mesh (a
// smaller admissible set: stiffer, a bound), plane stress the thin-gear limit (softer): the 3D k
// lies between them and its TE between their TEs. Measured 2026-11-26 (Q1, 8 layers, 24 mm):
// k 279.06 N/µm in 3D against 285.93 plane strain (−2.4 %) and 267.54 plane stress (+4.3 %); TE
// 7.176 against 7.004 (+2.5 %) and 7.485 µm. The 3D line load is not uniform: the free end faces
// (σ_zz = 0 there) carry 1.5 % more than the middle of the face (84.20 against 82.95 N/mm),
// K_Hβ = 1.009 (regression, held to ±0.003). The pressures integrated over the flank give the
// pair's normal force (the sum of its mortar multipliers) exactly: the nodal pressure is the
// multiplier over its shape function's integral, and on the z-extruded bilinear faces the
// trapezoidal rule over the nodes integrates that interpolant exactly (held to 1e-9).
TEST(LeadModification, TwoDAgainstThreeD)
{
  GearMeshStiffnessSettings settings = coarse_3d("lead_2d3d");
  const GearMeshStiffnessResult solid = solve<3>(settings);
  settings.scene.mesh.dimension = 2;
  const GearMeshStiffnessResult strain = solve<2>(settings);
  settings.elasticity.model = fem::PlanarModel::plane_stress;
  const GearMeshStiffnessResult stress = solve<2>(settings);
  const FaceLoadSummary s = summarise_face_load(solid.face_load);
  print("3D unmodified", solid, s);
  std::cout << "plane strain k " << strain.mesh_stiffness / 1e6 << " N/um, TE "
            << strain.transmission_error * 1e6 << " um; plane stress k "
            << stress.mesh_stiffness / 1e6 << " N/um, TE " << stress.transmission_error * 1e6
            << " um\n";
  EXPECT_LT(solid.mesh_stiffness, strain.mesh_stiffness);
  EXPECT_GT(solid.mesh_stiffness, stress.mesh_stiffness);
  EXPECT_GT(solid.transmission_error, strain.transmission_error);
  EXPECT_LT(solid.transmission_error, stress.transmission_error);
  EXPECT_EQ(s.z.size(), settings.scene.mesh.layers + 1);
  EXPECT_NEAR(s.force, summed_normal_force(solid), 1e-9 * summed_normal_force(solid));
  EXPECT_NEAR(s.factor, 1.009, 0.003);
  EXPECT_GT(s.line_load.front(), s.line_load[s.z.size() / 2]);
}

// Symmetric lead crowning C_β = 10 µm on the pinion (both flanks): the scene, its mesh and its
// load are mirror-symmetric about z = b/2 (the transverse mesh is the same on every layer), so
// w(z) = w(b − z) to the solver's precision (held to 1e-6 of the peak), the peak lies on the middle
// layer and the crowning concentrates the load there: K_Hβ well above the unmodified one
// (measured 2026-11-26: 1.849, the ends of the face unloaded, TE 10.21 µm against 7.18 µm
// unmodified; regression, ±0.01). A slice model (independent strips of the unmodified line
// stiffness k/b, no coupling across the face) would keep the whole face loaded, K_Hβ 1.46 and TE
// 10.51 µm: the FE's shear coupling between the strips lets the middle carry more.
TEST(LeadModification, CrowningPeaksMidWidth)
{
  geometry::LeadModification crowning;
  crowning.crowning = 10e-6;
  const FaceLoadSummary s =
      pinion_lead_face_load("lead_crowning", crowning, "3D lead crowning 10 um");
  const double b = face_width();
  EXPECT_NEAR(s.peak_z, 0.5 * b, 1e-9);
  EXPECT_NEAR(s.factor, 1.849, 0.01);
  const std::size_t n = s.z.size();
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(s.line_load[i], s.line_load[n - 1 - i], 1e-6 * s.peak) << "z = " << s.z[i];
  EXPECT_LT(s.line_load.front(), 0.5 * s.peak);
}

// Where the peak acts when the face carries the same line load at several planes: the plane
// nearest z = 0, whatever the round-off between them (helical.beta_zero failed on a fresh clone,
// session 43, when a β = 1e-7° run's ends differed by 1.9e-9 relative and the peak flipped to
// z = b). The ends here differ by 1e-9 the other way round, and a genuine peak 1e-5 above its
// neighbours keeps its place.
TEST(LeadModification, PeakOfEqualEndsAtZeroFace)
{
  const auto summary = [](const std::vector<double>& w)
  {
    std::vector<FaceLoadPoint> points;
    for (std::size_t i = 0; i < w.size(); ++i)
      points.push_back({0, 0.012 * static_cast<double>(i), w[i], 0.012});
    return summarise_face_load(points);
  };
  EXPECT_EQ(summary({76.41044543e3, 75.4165363e3, 76.41044550e3}).peak_z, 0.);
  EXPECT_EQ(summary({76.41044550e3, 75.4165363e3, 76.41044543e3}).peak_z, 0.);
  EXPECT_EQ(summary({76.4e3, 75.4e3, 76.4e3 * (1. + 1e-5)}).peak_z, 0.024);
}

// Lead slope f_Hβ = +10 µm on the pinion removes material towards z = b: the load moves to z = 0,
// where the flanks are unmodified (the peak at the z = 0 face, the load centroid in the first
// third of the face). Measured 2026-11-26: K_Hβ 2.070, w falling from 172.8 N/mm at z = 0 to
// 1.4 N/mm at z = b (regression, ±0.01).
TEST(LeadModification, SlopeMovesLoadToOneEnd)
{
  geometry::LeadModification slope;
  slope.slope = 10e-6;
  const FaceLoadSummary s = pinion_lead_face_load("lead_slope", slope, "3D lead slope +10 um");
  EXPECT_NEAR(s.peak_z, 0., 1e-9);
  double moment = 0.;
  for (std::size_t i = 1; i < s.z.size(); ++i)
    moment += 0.25 * (s.line_load[i - 1] + s.line_load[i]) * (s.z[i] + s.z[i - 1]) *
              (s.z[i] - s.z[i - 1]);
  EXPECT_LT(moment / s.force, face_width() / 3.);
  EXPECT_NEAR(s.factor, 2.070, 0.01);
  // verification.face_load_iso: ISO 6336-1 method C (docs/references.md §15) for the linear gap
  // it is written for, F_βy = f_Hβ = 10 µm, with c_γβ = 0.85·c_γα = 15.69 N/(mm·µm) (method B,
  // `gearstiff gear-pair`) and F_m/b = 78.41 N/mm: 1 + F_βy·c_γβ/(2F_m/b) > 2, so
  // K_Hβ = √(2F_βy·c_γβ/(F_m/b)) = 2.001 (docs/micro-geometry.md). Measured 2026-11-26: FE 2.070,
  // +3.5 %. Held within 5 %: ISO's elastic foundation against the FE's plate is a model
  // difference, not a discretisation error (the crowned face differs by +12 to +38 %), and the
  // 5 % band is the claim docs/accuracy.md states for the slope.
  const double iso = std::sqrt(2. * 10. * 15.69 / 78.41);
  std::cout << "K_Hbeta FE " << s.factor << " against ISO 6336-1 method C " << iso << ": "
            << 100. * (s.factor / iso - 1.) << " % (tolerance 5 %)\n";
  EXPECT_NEAR(s.factor / iso, 1., 0.05);
}
