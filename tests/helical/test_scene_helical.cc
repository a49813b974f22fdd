// The helical gear-pair scene (issue 46, docs/helical.md): the split-path pair of
// docs/references.md §1 with β = ±15° (ISO 21771:2007 formulas in the comments), meshed coarsely
// in 3D. Checks the contact lines the scene exposes across the face, the pairs it models, that the
// twisted mesh passes the cell checks, and the refusals before gmsh runs.
#include "errors/errors.h"
#include "geometry/scene_gear_pair.h"
#include "kinematics/gear_pair.h"
#include "tests/test_paths.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>
#include <string>
#include <unistd.h>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;

constexpr double degree = M_PI / 180.;

GearPairSceneSpec helical_spec(double beta_degrees, unsigned int dimension = 3)
{
  GearPairSceneSpec spec;
  spec.pair.pinion.helix_angle = beta_degrees * degree; // right hand
  spec.pair.wheel.helix_angle = -beta_degrees * degree; // left hand (external pair)
  // Standard tips (the command's `auto`): the published tips are the spur pair's.
  spec.pair.pinion.tip_diameter = spec.pair.wheel.tip_diameter = 0.;
  spec.mesh.dimension = dimension;
  spec.mesh.layers = 8;
  // Coarse sizes: the test checks the geometry, not a converged mesh.
  spec.mesh.contact_size = 0.2e-3;
  spec.mesh.body_size = 1.0e-3;
  return spec;
}

// <build>/tests/helical/work/scene_<name>-<pid>.msh: in the build, not /tmp, and one a process —
// fixed names in /tmp were shared by every build's tests on the machine (a clone's and a reused
// build's ran into each other) and outlived the test (3.9 MB found there).
std::string scene_file(const std::string& name)
{
  return (test_support::build_work_folder("tests/helical/work") /
          ("scene_" + name + "-" + std::to_string(getpid()) + ".msh"))
      .string();
}

std::string refusal(const GearPairSceneSpec& spec)
{
  try
  {
    write_gear_pair_scene(spec, scene_file("refused"));
  }
  catch (const InputError& e)
  {
    EXPECT_FALSE(std::filesystem::exists(scene_file("refused")));
    return e.parameter();
  }
  return "";
}

// The contact lines lie in the plane of action, inclined at β_b to the axis: along the face the
// transverse contact moves by tan β_b per unit z (ISO 21771: tan β_b = tan β·cos α_t), and every
// pair touches over the part of the face where it lies inside the path of contact.
TEST(HelicalScene, ContactLinesAreInclinedAtTheBaseHelixAngle)
{
  std::filesystem::remove(scene_file("lines"));
  const GearPairSceneSpec spec = helical_spec(15.);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const GearPairScene scene = write_gear_pair_scene(spec, scene_file("lines"));
  const double tan_beta_b = std::tan(pair.base_helix_angle);
  EXPECT_NEAR(tan_beta_b, std::tan(15. * degree) * std::cos(pair.transverse_pressure_angle), 1e-15);
  ASSERT_EQ(scene.contact_lines.size(), scene.contact_pairs.size());
  // ε_α + ε_β = 1.75 + 0.79: three pairs touch somewhere across the face.
  EXPECT_EQ(scene.contact_pairs.size(), 3u);
  const double b = pair.common_face_width;
  double total = 0.;
  for (const ContactLine& line : scene.contact_lines)
  {
    const double dz = line.end.z() - line.start.z();
    ASSERT_GT(dz, 0.);
    EXPECT_NEAR((line.end_position - line.start_position) / dz, tan_beta_b, 1e-12);
    EXPECT_NEAR((line.end - line.start).head<2>().norm() / dz, tan_beta_b, 1e-12);
    EXPECT_GE(line.start.z(), 0.);
    EXPECT_LE(line.end.z(), b);
    EXPECT_GE(std::min(line.start_position, line.end_position), pair.contact_start - 1e-12);
    EXPECT_LE(std::max(line.start_position, line.end_position), pair.contact_end + 1e-12);
    total += dz;
  }
  // The lines' axial extents add up to the face width times ε_α when no line is cut by a face
  // end within the path; here they are cut, so only the bounds hold: ε_α·b·(1 ± ε_β/ε_α).
  EXPECT_GT(total, b);
  EXPECT_LT(total, (pair.transverse_contact_ratio + pair.overlap_ratio) * b);
  EXPECT_TRUE(std::filesystem::exists(scene_file("lines")));
  EXPECT_GT(scene.info.mesh.min_scaled_jacobian, 0.);
  EXPECT_LE(scene.info.mesh.largest_edge_ratio_at_focus, 1.05);
  std::filesystem::remove(scene_file("lines"));
}

// A spur pair's lines are parallel to the axis over the whole face, one per pair in contact.
TEST(HelicalScene, SpurContactLinesAreAxial)
{
  GearPairSceneSpec spec = helical_spec(0.);
  spec.mesh.layers = 2;
  const GearPairScene scene = write_gear_pair_scene(spec, scene_file("spur"));
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  ASSERT_EQ(scene.contact_lines.size(), scene.contact_pairs.size());
  for (const ContactLine& line : scene.contact_lines)
  {
    EXPECT_EQ(line.start_position, line.end_position);
    EXPECT_EQ(line.start.z(), 0.);
    EXPECT_EQ(line.end.z(), pair.common_face_width);
  }
  std::filesystem::remove(scene_file("spur"));
}

// Refused before gmsh runs, each naming its library field (app maps them to the parameter the
// user typed: `Mesh/dimension`, `Mesh/layers`, checked by the cli.helical_* refusal tests).
TEST(HelicalScene, RefusesWhatItCannotMesh)
{
  EXPECT_EQ(refusal(helical_spec(15., 2)), "mesh.dimension");
  GearPairSceneSpec few = helical_spec(15.);
  few.mesh.layers = 6; // 8·ε_β = 6.33 needs 7
  EXPECT_EQ(refusal(few), "mesh.layers");
  few.mesh.layers = 7;
  EXPECT_EQ(layers_for_twist(kinematics::compute_gear_pair(few.pair)), 7u);
  EXPECT_EQ(refusal(helical_spec(45.)), "pinion.helix_angle");
  GearPairSceneSpec swept = helical_spec(15.); // a rolling sweep runs; off the path it cannot
  swept.swept_positions = {1.};
  EXPECT_EQ(refusal(swept), scene_field::swept_positions);
}

// The pair of the face-width study (docs/helical.md "Face width and ε_β": z 19/29, m_n 2 mm,
// x 0, β ±20°) at the face width b = ε_β·π·m_n/sin β (ISO 21771) of `overlap_ratio`.
GearPairSceneSpec study_spec(double overlap_ratio)
{
  GearPairSceneSpec spec = helical_spec(20.);
  for (kinematics::GearSpec* gear : {&spec.pair.pinion, &spec.pair.wheel})
  {
    gear->normal_module = 2e-3;
    gear->profile_shift = 0.;
    gear->face_width = overlap_ratio * M_PI * 2e-3 / std::sin(20. * degree);
  }
  spec.pair.pinion.teeth = 19;
  spec.pair.wheel.teeth = 29;
  spec.mesh.layers = static_cast<unsigned int>(std::ceil(16. * overlap_ratio)); // the default
  spec.pinion_teeth_modelled = spec.wheel_teeth_modelled = 3; // the stiffness command's
  spec.pinion_teeth_follow_pairs = spec.wheel_teeth_follow_pairs = true;
  return spec;
}

// `Gear pair scene/... teeth modelled = auto` (docs/helical.md "Teeth modelled"): the command's
// count, raised to every pair that can touch across the face at any position of the mesh cycle.
// The study found by hand that ε_β 2 and 2.2 need a fourth tooth on each gear (the pairs ±2 touch
// near the face ends, ε_β > 2(2 − ε_α) ≈ 1.06 with ε_α 1.47), and ran ε_β ≤ 1.5 on three; spur
// pairs keep the count. A count given is kept, and refused below the pairs at its position
// naming the field (no gmsh: the refusal comes first).
TEST(HelicalScene, TeethModelledFollowThePairsAcrossTheFace)
{
  for (const auto& [overlap, teeth] :
       {std::pair{0.5, 3u}, std::pair{1.5, 3u}, std::pair{2.0, 4u}, std::pair{2.2, 4u}})
  {
    const GearPairSceneSpec chosen = with_teeth_modelled(study_spec(overlap));
    EXPECT_EQ(chosen.pinion_teeth_modelled, teeth) << "ε_β " << overlap;
    EXPECT_EQ(chosen.wheel_teeth_modelled, teeth) << "ε_β " << overlap;
  }
  GearPairSceneSpec spur = study_spec(2.0);
  spur.pair.pinion.helix_angle = spur.pair.wheel.helix_angle = 0.;
  EXPECT_EQ(with_teeth_modelled(spur).pinion_teeth_modelled, 3u);
  GearPairSceneSpec built_in = helical_spec(15.); // ε_β 0.79
  built_in.pinion_teeth_modelled = built_in.wheel_teeth_modelled = 3;
  built_in.pinion_teeth_follow_pairs = built_in.wheel_teeth_follow_pairs = true;
  EXPECT_EQ(with_teeth_modelled(built_in).pinion_teeth_modelled, 3u);

  // A count given (follow_pairs false) is kept; at a position where four pairs touch across the
  // face it is refused naming the field.
  GearPairSceneSpec given = study_spec(2.2);
  given.pinion_teeth_follow_pairs = given.wheel_teeth_follow_pairs = false;
  EXPECT_EQ(with_teeth_modelled(given).pinion_teeth_modelled, 3u);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(given.pair);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  bool found = false;
  for (int k = 0; k < 24 && !found; ++k)
  {
    const double position = pair.contact_start + (k + 0.5) / 24. * pair.transverse_base_pitch;
    if (gear_pairs_across_face(pair, position).size() < 4)
      continue;
    found = true;
    given.position = PairPosition::roll_angle;
    given.pinion_roll_angle = position / r_b1;
    EXPECT_EQ(refusal(given), scene_field::pinion_teeth_modelled);
  }
  EXPECT_TRUE(found) << "no position of the cycle has four pairs across the face";
}

// The defaults a helical pair takes (docs/helical.md "Default mesh"): the built-in pair at
// β ±15° (ε_β 0.79) gets 16 per unit of ε_β, 13 layers (the ladder: 10 layers −0.36 % against
// 14, 7 layers +2.07 %; a mortar gap ≈ −0.32 µm within half the 1 µm tolerance) and twice the
// spur body size, 1.4 mm (the ladder's; 0.7 mm exceeds the cell limit at 8 layers already). A
// narrow face keeps the spur count (8), and a spur pair keeps the spur defaults exactly.
TEST(HelicalScene, DefaultMeshFollowsTheContactLines)
{
  SceneMeshSettings spur; // the stiffness command's defaults for the built-in pair
  spur.dimension = 3;
  spur.layers = 8;
  spur.body_size = 0.7e-3;
  const GearPairSceneSpec built_in = helical_spec(15.);
  const SceneMeshSettings helical =
      helical_mesh_defaults(spur, kinematics::compute_gear_pair(built_in.pair));
  EXPECT_EQ(helical.layers, 13u);
  EXPECT_DOUBLE_EQ(helical.body_size, 1.4e-3);
  EXPECT_EQ(helical.contact_size, spur.contact_size);
  GearPairSceneSpec narrow = helical_spec(5.); // ε_β 0.26: 16·ε_β = 4.2 < 8
  EXPECT_EQ(helical_mesh_defaults(spur, kinematics::compute_gear_pair(narrow.pair)).layers, 8u);
  const SceneMeshSettings same =
      helical_mesh_defaults(spur, kinematics::compute_gear_pair(helical_spec(0.).pair));
  EXPECT_EQ(same.layers, 8u);
  EXPECT_EQ(same.body_size, spur.body_size);
}

// ISO 21771 hands: an external pair with one hand, an internal pair with two.
TEST(HelicalScene, RefusesWrongHands)
{
  kinematics::GearPairSpec pair = helical_spec(15.).pair;
  pair.wheel.helix_angle = pair.pinion.helix_angle;
  try
  {
    kinematics::compute_gear_pair(pair);
    FAIL() << "same hands accepted on an external pair";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "wheel.helix_angle");
  }
}

// δ_t = δ_n / cos β_b: the transverse outline removes more than the normal amount given.
TEST(HelicalScene, ModificationsAreConvertedToTheTransverseSection)
{
  GearPairSceneSpec spec = helical_spec(15.);
  ToothModification relief;
  relief.kind = ModificationKind::tip_relief;
  relief.amount = 10e-6;
  relief.length = 1e-3;
  spec.pinion_modifications.all_teeth.push_back(relief);
  spec.pinion_modifications.lead.crowning = 5e-6;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const GearPairSceneSpec section = transverse_section_spec(spec);
  const double c = std::cos(pair.base_helix_angle);
  EXPECT_NEAR(section.pinion_modifications.all_teeth.front().amount, 10e-6 / c, 1e-18);
  EXPECT_NEAR(section.pinion_modifications.lead.crowning, 5e-6 / c, 1e-18);
  EXPECT_EQ(transverse_section_spec(helical_spec(0.)).pinion_modifications.all_teeth.size(), 0u);
}
} // namespace

// The hexahedra of a twisted body have straight edges between two layers: the trilinear point
// of a lateral face is the section point q turned by (1 − t)·R(φ_k) + t·R(φ_k+1), a chord of
// q's helix. BodyTwist::on_helix returns R(φ(z))·q, the point of the helicoid it stands for —
// exactly (to round-off) for every point of such a face, and the nodes themselves unchanged.
// The twists are the scene's: the pinion turned forward by tan β_b/r_b1 per metre of face, the
// external wheel backward by r_b1/r_b2 as much, both about their axes, the same at z = b/2.
TEST(HelicalScene, FlanksBetweenLayersAreTurnedBackOntoTheirHelicoids)
{
  const GearPairSceneSpec spec = helical_spec(15.);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const std::map<int, BodyTwist> twists = gear_pair_twists(pair);
  ASSERT_EQ(twists.size(), 2u);
  const BodyTwist& pinion = twists.at(scene_ids::pinion_body);
  const BodyTwist& wheel = twists.at(scene_ids::wheel_body);
  const double r_b1 = 0.5 * pair.pinion.base_diameter, r_b2 = 0.5 * pair.wheel.base_diameter;
  EXPECT_NEAR(pinion.rate, std::tan(pair.base_helix_angle) / r_b1, 1e-12);
  EXPECT_NEAR(wheel.rate, -pinion.rate * r_b1 / r_b2, 1e-12);
  EXPECT_NEAR(wheel.axis.x(), pair.centre_distance, 1e-15);
  EXPECT_EQ(pinion.origin, 0.5 * pair.common_face_width);
  EXPECT_TRUE(gear_pair_twists(kinematics::compute_gear_pair(helical_spec(0.).pair)).empty());

  // Two nodes of a flank face in the section and the layer planes of 4 layers.
  const Eigen::Vector2d p_a(0.5e-3, 27.0e-3), p_b(1.2e-3, 28.5e-3);
  const double layer = pair.common_face_width / 4., z_k = layer, z_k1 = 2. * layer;
  const auto node = [&](const Eigen::Vector2d& p, double z) { return pinion.turned(p, z); };
  double largest_chord_error = 0.;
  for (const double s : {0., 0.3, 1.})
    for (const double t : {0., 0.25, 0.5, 0.9, 1.})
    {
      const Eigen::Vector2d meshed = (1. - s) * (1. - t) * node(p_a, z_k) +
                                     s * (1. - t) * node(p_b, z_k) +
                                     (1. - s) * t * node(p_a, z_k1) + s * t * node(p_b, z_k1);
      const double z = (1. - t) * z_k + t * z_k1;
      const Eigen::Vector2d exact = pinion.turned((1. - s) * p_a + s * p_b, z);
      const Eigen::Vector3d back = pinion.on_helix({meshed.x(), meshed.y(), z}, z_k, z_k1);
      EXPECT_NEAR((back.head<2>() - exact).norm(), 0., 1e-15) << "s " << s << " t " << t;
      EXPECT_EQ(back.z(), z);
      largest_chord_error = std::max(largest_chord_error, (meshed - exact).norm());
    }
  // The chord's error the correction removes: r·Δφ²/8 at mid-layer (r ≈ 28 mm, Δφ = rate·b/4).
  const double dphi = pinion.rate * layer;
  EXPECT_NEAR(largest_chord_error, 28.5e-3 * dphi * dphi / 8., 0.1 * 28.5e-3 * dphi * dphi / 8.);
}
