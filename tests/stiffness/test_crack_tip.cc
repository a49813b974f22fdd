// Stress intensity factors from the FE (stiffness/crack_tip.h) on the handbook case: an edge
// crack of depth a in a strip of width b under bending M and tension N (per unit thickness),
// Tada, Paris & Irwin, The Stress Analysis of Cracks Handbook (docs/references.md §16), s = a/b,
// t = πs/2:
//
//     K_I = √(πa) (σ_M F_M(s) + σ_N F_N(s)),  σ_M = 6M/b², σ_N = N/b,
//     F_M(s) = √(tan t / t) (0.923 + 0.199 (1 − sin t)⁴) / cos t   (pure bending),
//     F_N(s) = √(tan t / t) (0.752 + 2.02 s + 0.37 (1 − sin t)³) / cos t   (tension),
//
// both "better than 0.5 % for any a/b" in the handbook. The strip is meshed with the project's
// own tools (geometry/mesh_planar.h: the crack a cut of zero width whose faces are a contact pair
// of the strip with itself, contact/contact_problem.h), 2D plane strain Q2, its ends turned
// rigidly by ∓θ about their middles (rigid hubs): bending 2b away from the crack (Saint-Venant).
// The hubs hold the ends' middles, so the opened crack (whose section bends about a point above
// the middle) also draws an axial force N: it is measured (the hub's reaction) and superposed,
// as the handbook's factors allow in linear elasticity. Bent one way the crack opens (K_I against
// Tada); bent the other way its faces close and the strip is as stiff as without the crack.
#include "contact/contact_problem.h"
#include "errors/errors.h"
#include "fem/mesh.h"
#include "geometry/mesh_planar.h"
#include "stiffness/crack_tip.h"
#include "stiffness/mesh_stiffness.h"
#include "tests/stiffness/work_file.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;

namespace
{
constexpr double width = 10e-3;       // m, b
constexpr double length = 4. * width; // m, the crack at its middle
constexpr double young = 210e9, poisson = 0.3;
constexpr int left_end = 1, right_end = 2, crack_face = 11;

// Tada, Paris & Irwin: F(a/b) of the edge crack under pure bending and under tension (above).
double bending_factor(double s)
{
  const double t = 0.5 * M_PI * s;
  return std::sqrt(std::tan(t) / t) * (0.923 + 0.199 * std::pow(1. - std::sin(t), 4)) / std::cos(t);
}

double tension_factor(double s)
{
  const double t = 0.5 * M_PI * s;
  return std::sqrt(std::tan(t) / t) * (0.752 + 2.02 * s + 0.37 * std::pow(1. - std::sin(t), 3)) /
         std::cos(t);
}

// The widely reproduced polynomial fit of the bending factor (printed beside, not tested).
double bending_polynomial(double s)
{
  return 1.122 - 1.40 * s + 7.33 * s * s - 13.08 * s * s * s + 14.0 * s * s * s * s;
}

geometry::BoundaryPiece straight(Eigen::Vector2d from, Eigen::Vector2d to, int id)
{
  geometry::BoundaryPiece piece;
  piece.kind = geometry::CurveKind::straight;
  piece.points = {from, to};
  piece.boundary_id = id;
  return piece;
}

// The strip with an edge crack of depth `depth` from the middle of its lower edge (0: none),
// cells of `tip` at the tip (within 10 tip), 2 tip along the faces, as the gear's cracks. With a
// crack the strip is cut along mouth → tip → the upper edge: the right half is a fill
// (geometry/mesh_planar.h PlanarFill::crack_id), so the mesh follows the crack.
void write_strip(double depth, double tip, const std::string& file)
{
  geometry::PlanarBody body;
  body.name = "strip";
  const Eigen::Vector2d mouth(0.5 * length, 0.), crack_tip(0.5 * length, depth),
      top(0.5 * length, width);
  geometry::SizeGrading grading;
  grading.body_size = grading.largest_size = width / 8.;
  grading.foci.push_back({crack_tip, tip, 10. * tip});
  if (depth > 0.)
  {
    body.outer.pieces = {straight({0., 0.}, mouth, 0), straight(mouth, crack_tip, crack_face),
                         straight(crack_tip, top, 0), straight(top, {0., width}, 0),
                         straight({0., width}, {0., 0.}, left_end)};
    geometry::PlanarFill fill;
    fill.first_piece = 1;
    fill.last_piece = 2;
    fill.closing = {straight(top, {length, width}, 0),
                    straight({length, width}, {length, 0.}, right_end),
                    straight({length, 0.}, mouth, 0)};
    fill.crack_id = crack_face;
    body.fills.push_back(fill);
    const unsigned int n = static_cast<unsigned int>(std::ceil(depth / (4. * tip)));
    for (unsigned int k = 0; k < n; ++k)
      grading.foci.push_back({mouth + Eigen::Vector2d(0., depth * k / n), 2. * tip, 4. * tip});
  }
  else
    body.outer.pieces = {
        straight({0., 0.}, {length, 0.}, 0), straight({length, 0.}, {length, width}, right_end),
        straight({length, width}, {0., width}, 0), straight({0., width}, {0., 0.}, left_end)};
  geometry::PlanarModel model;
  model.bodies = {body};
  model.boundary_names = {{left_end, "left end"}, {right_end, "right end"}};
  geometry::MeshOptions options;
  options.file = file;
  geometry::mesh_planar_model(model, grading, options);
}

struct StripResult
{
  double moment = 0.; // N·m per m of thickness, about the right end's middle
  double axial = 0.;  // N per m of thickness, tension in the strip (the right hub's reaction)
  stiffness::CrackTipFactors tip;
  unsigned int cells = 0;
};

// The strip bent by turning its right end by θ and its left end by −θ (θ > 0 opens a crack on
// the lower edge).
StripResult bend_strip(double depth, double tip, double theta, const std::string& name)
{
  const std::string file = stiffness_work_stem(name) + ".msh";
  write_strip(depth, tip, file);
  fem::ElasticityParameters elasticity = stiffness::default_stiffness_elasticity();
  elasticity.thickness = 1.;
  contact::ContactProblem<2> problem(MPI_COMM_SELF, elasticity, {}, {});
  fem::read_msh<2>(file, 1., problem.system().triangulation(), "strip");
  std::filesystem::remove(file);
  fem::Material steel;
  steel.youngs_modulus = young;
  steel.poisson_ratio = poisson;
  problem.system().set_materials({{1, steel}}, "material");
  using Control = fem::RigidHub<2>::Control;
  problem.add_rigid_hub(left_end, dealii::Point<2>(0., 0.5 * width), Control::rotation, -theta,
                        "left end");
  problem.add_rigid_hub(right_end, dealii::Point<2>(length, 0.5 * width), Control::rotation, theta,
                        "right end");
  if (depth > 0.)
    problem.add_contact_pair({crack_face}, {crack_face + 1}, "crack faces", {}, true);
  problem.run();
  StripResult r;
  r.moment = std::abs(problem.results().supports.at(1).torque);
  r.axial = problem.results().supports.at(1).force[0];
  r.cells = problem.system().triangulation().n_active_cells();
  if (depth > 0.)
    r.tip = stiffness::crack_tip_factors(
        problem.system().get_dof_handler(), problem.system().get_mapping(), problem.solution(),
        crack_face, crack_face + 1, young / (1. - poisson * poisson),
        stiffness::crack_fit_from * tip, stiffness::crack_fit_to * tip);
  return r;
}

double tada_mode_one(const StripResult& r, double depth)
{
  const double s = depth / width;
  return std::sqrt(M_PI * depth) * (6. * r.moment / (width * width) * bending_factor(s) +
                                    r.axial / width * tension_factor(s));
}

constexpr double theta = 1e-4; // rad: bending stress ≈ E θ b /L ≈ 100 MPa, small strain

// K_I of the opened crack (a/b = 0.5, tip cells 10 µm; a/b = 0.3 at four sizes is the
// refinement study below) against Tada within 5 % (the tolerance; measured +2.0 %);
// K_II vanishes by symmetry (|K_II| < 1 % K_I; measured 0.04 %).
TEST(CrackTip, EdgeCrackInBendingAgainstTada)
{
  for (const double s : {0.5})
  {
    const double a = s * width;
    const StripResult r = bend_strip(a, 10e-6, theta, "strip_open");
    const double reference = tada_mode_one(r, a);
    std::cout << "a/b " << s << ": K_I FE " << r.tip.mode_one * 1e-6 << " MPa m^0.5, Tada "
              << reference * 1e-6 << " (" << 100. * (r.tip.mode_one / reference - 1.)
              << " %), K_II " << r.tip.mode_two * 1e-6 << ", " << r.tip.fit_nodes
              << " nodes fitted, " << r.cells << " cells; N/(6M/b) "
              << r.axial * width / (6. * r.moment) << ", F_M " << bending_factor(s)
              << " (polynomial " << bending_polynomial(s) << ")\n";
    EXPECT_NEAR(r.tip.mode_one / reference, 1., 0.05);
    EXPECT_LT(std::abs(r.tip.mode_two), 0.01 * r.tip.mode_one);
    EXPECT_NEAR(r.tip.length, a, 1e-9);
  }
}

// Bent the other way the crack's faces are pressed together: K_I vanishes (|K_I| < 1 % of the
// opened crack's; measured 0.4 %) and the strip keeps the stiffness of the uncracked one (within
// 0.1 %: the faces carry the compression, only the mesh differs; measured 0.01 %), while opened
// it loses a share of it (measured 17.7 %). Tip cells 20 µm (the refinement study: K_I within
// 0.4 % of the 10 µm value).
TEST(CrackTip, ClosedCrackCarriesCompression)
{
  const double a = 0.3 * width;
  const StripResult healthy = bend_strip(0., 20e-6, theta, "strip_healthy");
  const StripResult opened = bend_strip(a, 20e-6, theta, "strip_opened");
  const StripResult closed = bend_strip(a, 20e-6, -theta, "strip_closed");
  std::cout << "bending stiffness: uncracked " << healthy.moment / theta << " N m/rad, opened "
            << 100. * (opened.moment / healthy.moment - 1.) << " %, closed "
            << 100. * (closed.moment / healthy.moment - 1.) << " %; closed K_I "
            << closed.tip.mode_one * 1e-6 << " MPa m^0.5 (opened " << opened.tip.mode_one * 1e-6
            << ")\n";
  EXPECT_LT(opened.moment, 0.95 * healthy.moment);
  EXPECT_NEAR(closed.moment / healthy.moment, 1., 1e-3);
  EXPECT_LT(std::abs(closed.tip.mode_one), 0.01 * opened.tip.mode_one);
}

// Crack-tip refinement on the strip (a/b = 0.3): tip cells 40, 20, 10, 5 µm (faces 2 h_tip,
// h_tip within 10 h_tip of the tip). Each K_I within 5 % of Tada; between the two finest sizes
// K_I moves by less than 1.5 % (measured 0.7 %) and the bending stiffness M/θ by less than 0.01 %
// (measured 0.001 %): the converged error stated in docs/faults.md.
TEST(CrackTip, RefinementStudy)
{
  const double a = 0.3 * width;
  double previous = 0., previous_stiffness = 0.;
  for (const double tip : {40e-6, 20e-6, 10e-6, 5e-6})
  {
    const auto start = std::chrono::steady_clock::now();
    const StripResult r = bend_strip(a, tip, theta, "strip_refine");
    const double reference = tada_mode_one(r, a);
    std::cout << "tip " << tip * 1e6 << " um: K_I " << r.tip.mode_one * 1e-6 << " MPa m^0.5 ("
              << 100. * (r.tip.mode_one / reference - 1.) << " % vs Tada"
              << (previous > 0. ? ", " + std::to_string(100. * (r.tip.mode_one / previous - 1.)) +
                                      " % vs the previous size"
                                : std::string())
              << "), M/theta " << r.moment / theta << ", " << r.cells << " cells, "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s\n";
    EXPECT_NEAR(r.tip.mode_one / reference, 1., 0.05);
    if (tip < 6e-6)
    {
      EXPECT_NEAR(r.tip.mode_one / previous, 1., 0.015);
      EXPECT_NEAR(r.moment / theta / previous_stiffness, 1., 1e-4);
    }
    previous = r.tip.mode_one;
    previous_stiffness = r.moment / theta;
  }
}
} // namespace
