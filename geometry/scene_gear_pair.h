// The FE scene of a spur or helical gear pair at one pinion position: a few teeth of each gear
// around the predicted contacts, their rim down to the bore (a sector with cut faces, or the full
// rim with the other teeth removed, as in the ANSYS model of Reszuta & Drewniak 2015), the wheel
// placed in mesh, contact points predicted along the line of action.
//
// Internal pairs (ring wheel): the ring centre at (−a_w, 0), its rim held (boundary id "wheel
// bore") on its outer circle — the whole circle, or N pads of it (a ring splined into a rigid
// housing at N points) — or at N bolt holes in the rim, the outer circle free (the mesh midway
// between two pads or holes), its loaded flank side −1, and pinion
// tooth j meshes ring tooth +j; T2 lies behind T1 on the line of action.
//
// Scene frame: pinion centre at the origin, wheel centre at (a_w, 0); the pinion drives counter-
// clockwise, so the line of action runs from T1 = r_b1·(cos α_wt, −sin α_wt) on the pinion base
// circle upwards through the pitch point to T2 on the wheel base circle, with direction
// u = (sin α_wt, cos α_wt). Loaded flanks: the +y side (side +1 of tooth_profile.h) of every
// pinion tooth and of every wheel tooth in its own frame. Positions along the line of action are
// distances ℓ from T1 (kinematics/gear_pair.h); the pinion roll angle is ℓ/r_b1.
//
// Tooth indices: pinion tooth j sits j angular pitches counter-clockwise of the reference tooth
// (j = 0, the pair at the chosen position); it meshes with wheel tooth −j. The pair j touches at
// ℓ_ref + j·p_bt.
#pragma once

#include "geometry/scene_common.h"
#include "geometry/tooth_modification.h"
#include "geometry/tooth_profile.h"
#include "kinematics/gear_pair.h"

#include <string>
#include <vector>

namespace gearstiff::geometry
{
enum class RimModel
{
  sector, // the rim of the modelled teeth only, cut radially through the outer gaps (ids 5, 6)
  full    // the whole rim and bore, teeth other than the modelled ones removed
};

// Where the reference pair (j = 0) touches.
enum class PairPosition
{
  single,      // pitch point if it lies in the single-contact zone, else that zone's middle
  double_pair, // middle of the first double-contact zone (the second pair then sits in the
               // middle of the last one)
  roll_angle   // GearPairSceneSpec::pinion_roll_angle
};

struct GearPairSceneSpec
{
  kinematics::GearPairSpec pair = kinematics::split_path_pair();

  PairPosition position = PairPosition::single;
  double pinion_roll_angle = 0.; // rad, ℓ_ref/r_b1 of the reference pair, within [A, E]

  unsigned int pinion_teeth_modelled = 5; // -, teeth of the pinion in the scene
  unsigned int wheel_teeth_modelled = 5;  // -, teeth of the wheel in the scene
  // `auto` (docs/helical.md "Teeth modelled"): the count above is the least modelled, raised to
  // every tooth pair that can touch (with_teeth_modelled); false: the count as given, refused
  // (InputError) when it cannot hold those pairs. A wide helical face (ε_β ≥ 2) needs a fourth
  // pair that the usual three teeth cannot hold, and the user should not have to guess it.
  bool pinion_teeth_follow_pairs = false;
  bool wheel_teeth_follow_pairs = false;
  double pinion_bore_radius = 0.; // m; 0: half of pair.pinion.bore_diameter
  double wheel_bore_radius = 0.;  // m; 0: half of pair.wheel.bore_diameter
  // m, internal wheel: rim thickness under the root circle, which sets its outer radius (held
  // fixed); 0: the outer radius is wheel_bore_radius (or half of pair.wheel.bore_diameter).
  double wheel_rim_thickness = 0.;
  // -, internal wheel with a full rim: 0 holds its whole outer circle; N ≥ 2 holds it only on N
  // pads of width wheel_support_width, evenly spaced, the pitch point midway between two (the
  // rim bends between the pads, as a ring bolted or splined into a rigid housing).
  unsigned int wheel_supports = 0;
  double wheel_support_width = 10e-3; // m, arc length of one pad on the outer circle
  // -, internal wheel with a full rim: N ≥ 2 bolts the ring at N circular holes in its rim
  // instead (the holes clamped, the outer circle free), evenly spaced at polar angles
  // (k + ½)·360°/N, the mesh midway between two; 0: no holes (wheel_supports applies).
  unsigned int wheel_bolt_holes = 0;
  double wheel_bolt_hole_diameter = 6.6e-3; // m, diameter of one hole (M6 clearance, ISO 273)
  double wheel_bolt_circle_diameter = 0.;   // m, of the hole centres; 0: the rim's middle
  RimModel rim = RimModel::sector;
  // A full rim's cells also grow with the arc distance from the modelled teeth, not only with the
  // depth below the root circle (up to the rim size): for a body whose compliance is only read at
  // the modelled teeth (the influence-coefficient model's FE body, docs/ltca.md §1), where the
  // rim far from them carries the load to the bore as a ring. false: every scene as before.
  bool rim_coarse_beyond_teeth = false;
  bool both_flanks = false; // also mark the unloaded flanks as candidate contact surfaces

  // The load and material only set the Hertz estimate of the default contact size.
  double pinion_torque = 49.4;  // N·m, T1 (docs/references.md §1: 7.5 kW at 1450 rpm)
  double young_modulus = 210e9; // Pa, both gears (steel; not published)
  double poisson_ratio = 0.3;   // -, both gears

  // Micro-geometry (and later faults) of the teeth: the scene asks a ToothProfiles provider for
  // every modelled tooth (geometry/tooth_modification.h); empty: every tooth nominal, the scene
  // bit-identical to one without the stage. InputError names "Gear pair/Pinion/..." and
  // "Gear pair/Wheel/...".
  GearModifications pinion_modifications;
  GearModifications wheel_modifications;

  SceneMeshSettings mesh;
  // m, rolling sweeps (one mesh turned to every position): the reference-pair positions ℓ the
  // bodies will be turned to from this scene's own position. Every flank that meshes at one of
  // them is refined along all the contact points it sees (the roll path sampled at half the fine
  // radius, mapped back to the body's own placement), and the modelled teeth cover every pair
  // in contact at one of them. Empty: this scene's own position only.
  std::vector<double> swept_positions;
  // Points per profile segment: dense enough that the spline through them follows the
  // involute to well below the contact size.
  ProfileResolution resolution = {4, 32, 160, 24, 12};
};

// Names of the spec's fields in the InputError the scene throws ("scene.<member>"); the
// command that fills the spec maps them to its own parameter names. Errors of the pair itself
// come from kinematics::compute_gear_pair and name "Gear pair/..." parameters.
namespace scene_field
{
inline const std::string position = "scene.position";
inline const std::string pinion_roll_angle = "scene.pinion_roll_angle";
inline const std::string pinion_teeth_modelled = "scene.pinion_teeth_modelled";
inline const std::string wheel_teeth_modelled = "scene.wheel_teeth_modelled";
inline const std::string pinion_bore_radius = "scene.pinion_bore_radius";
inline const std::string wheel_bore_radius = "scene.wheel_bore_radius";
inline const std::string wheel_rim_thickness = "scene.wheel_rim_thickness";
inline const std::string wheel_supports = "scene.wheel_supports";
inline const std::string wheel_support_width = "scene.wheel_support_width";
inline const std::string wheel_bolt_holes = "scene.wheel_bolt_holes";
inline const std::string wheel_bolt_hole_diameter = "scene.wheel_bolt_hole_diameter";
inline const std::string wheel_bolt_circle_diameter = "scene.wheel_bolt_circle_diameter";
inline const std::string both_flanks = "scene.both_flanks";
inline const std::string swept_positions = "scene.swept_positions";
inline const std::string pinion_torque = "scene.pinion_torque";
inline const std::string young_modulus = "scene.young_modulus";
inline const std::string poisson_ratio = "scene.poisson_ratio";
} // namespace scene_field

// Boundary ids of the tooth flanks: every modelled pinion tooth j writes its flanks with
// pinion_flank_id(j), the wheel tooth −j that meshes it with wheel_flank_id(j), so that each
// tooth pair is its own contact pair without any relabelling. |j| ≤ max_pair_index.
constexpr int max_pair_index = 99;
int pinion_flank_id(int pair);
int wheel_flank_id(int pair);
// Boundary ids of the two faces of a root crack whose faces meet (geometry/tooth_fault.h) on
// tooth `tooth` (|tooth| ≤ max_pair_index, the gear's own frame): crack_face_id and + 1.
int crack_face_id(bool wheel, int tooth);

// Where a pair's flanks touch across the face at the scene's position (unloaded, kinematic): a
// straight line in the plane of action, parallel to the axis for a spur pair and inclined at
// β_b to it for a helical one, over the part of the face where the pair lies inside the path of
// contact A–E (geometry/gear_pair_helix.cc). Scene frame, z from 0 to the face width.
struct ContactLine
{
  int pair = 0;                                    // -, j
  Eigen::Vector3d start = Eigen::Vector3d::Zero(); // m, the end at the smaller z
  Eigen::Vector3d end = Eigen::Vector3d::Zero();   // m
  double start_position = 0., end_position = 0.;   // m, ℓ from T1 at start and end
};

// A written gear-pair scene: the common SceneInfo and what this scene adds, by name.
struct GearPairScene
{
  SceneInfo info;                  // mesh, ids, predicted contacts (one per pair in contact)
  double reference_position = 0.;  // m, ℓ_ref of pair 0 along the line of action from T1
  double pinion_roll_angle = 0.;   // rad, ℓ_ref/r_b1
  std::vector<int> contact_pairs;  // -, j of the pairs inside the path of contact (A, E)
  std::vector<int> modelled_pairs; // -, j whose pinion and wheel teeth are both in the scene
  std::vector<int> swept_pairs; // -, j in contact at one of spec.swept_positions (or contact_pairs)
  double pinion_bore_radius = 0.;       // m
  double wheel_bore_radius = 0.;        // m
  double wheel_bolt_circle_radius = 0.; // m, of the ring's bolt-hole centres (0: no holes)
  double pinion_root_radius = 0.;       // m, of the meshed profile
  double wheel_root_radius = 0.;        // m
  double pinion_tip_radius = 0.;        // m
  double wheel_tip_radius = 0.;         // m
  double pinion_sector_angle = 0.;      // rad, angle spanned by the pinion body (full rim: 2π)
  double wheel_sector_angle = 0.;       // rad
  // The modifications' kinematic error at this position (the unloaded transmission error): the
  // smallest of the pairs' designed separations along the line of action, δ_pinion(ρ1) +
  // δ_wheel(ρ2) at each pair's kinematic contact point (0 without modifications).
  double unloaded_transmission_error = 0.; // m
  std::vector<double> pair_separation;     // m, of each pair in contact_pairs, same order
  // The contact line of each pair in contact_pairs (a helical pair's contact_pairs are every pair
  // in contact in some section across the face).
  std::vector<ContactLine> contact_lines;
};

// Helical pairs (ISO 21771; docs/helical.md): the sign of Gear pair/.../helix angle is the hand
// (β > 0 right hand). A helical pair is meshed in 3D only, its transverse section at the middle
// of the face twisted along the face by the lead.
bool is_helical(const GearPairSceneSpec& spec);
// The spec whose modification amounts are transverse: ISO 21771 gives them normal to the flank
// (δ_n), the transverse outline removes δ_t = δ_n / cos β_b. The spec itself for a spur pair.
GearPairSceneSpec transverse_section_spec(const GearPairSceneSpec& spec);
// -, the fewest layers across the face that follow a helical pair's twist: 8 per unit of ε_β.
unsigned int layers_for_twist(const kinematics::GearPairGeometry& pair);
// The default mesh settings of the pair's scene from the spur defaults: for a helical pair
// 16 layers per unit of ε_β (at least the spur count; they follow the contact lines, not only
// the twist) and twice the body size (so that they stay under the cell limit); `spur` itself for
// a spur pair. docs/helical.md "Default mesh".
SceneMeshSettings helical_mesh_defaults(const SceneMeshSettings& spur,
                                        const kinematics::GearPairGeometry& pair);
// The twist of both gears along the face (PlanarModel::twist, by material id: the pinion and
// the wheel body) in the frame of the written scene; empty for a spur pair. The solvers need it
// to put the meshed flanks back on their helicoids (BodyTwist::on_helix).
std::map<int, BodyTwist> gear_pair_twists(const kinematics::GearPairGeometry& pair);

// The roll-length ranges of the pinion (wheel = false) or the wheel flank against its mate
// (geometry/tooth_modification.h), from the pair and the generated tooth.
FlankRollRange flank_roll_range(const kinematics::GearPairGeometry& pair, const ToothProfile& tooth,
                                bool wheel);

// The spec with the teeth counts a scene models: a count that follows the pairs
// (pinion/wheel_teeth_follow_pairs) is raised to the tooth pairs that can touch — at the scene's
// position and every swept one, and for a helical pair across the face at every position of the
// mesh cycle, so that every position of a sweep models the same teeth; a count given stays.
// Milliseconds (no teeth generated); write_gear_pair_scene applies it.
GearPairSceneSpec with_teeth_modelled(const GearPairSceneSpec& spec);

// Checks the spec (InputError naming the field; all before gmsh runs), builds the scene,
// meshes it into `file` and returns what the FE module needs. Cost: well under a second in 2D.
GearPairScene write_gear_pair_scene(const GearPairSceneSpec& spec, const std::string& file);

// The checks of the modification stage alone (InputError naming "Gear pair/Pinion/..." or
// "Gear pair/Wheel/..."): generates both nominal teeth and checks every modification list
// against them. Milliseconds; write_gear_pair_scene makes the same checks.
void check_tooth_modifications(const GearPairSceneSpec& spec);
// The unloaded transmission error (m) a scene with its reference pair at each ℓ of `positions`
// (m from T1) would report (GearPairScene::unloaded_transmission_error): a rolling sweep meshes
// one scene, so each position it turns to takes its own value from here (issue 41: without it
// every rolled position reported the scene's own value). Generates the teeth once; no mesh.
std::vector<double> unloaded_transmission_errors(const GearPairSceneSpec& spec,
                                                 const std::vector<double>& positions);
// Rolling sweeps: the pairs j in contact (inside the path of contact A–E) with the reference
// pair at ℓ (m from T1), the same rule as the scene's contact_pairs.
std::vector<int> gear_pairs_in_contact(const kinematics::GearPairGeometry& pair, double position);
// The pairs j that touch somewhere across the face with the reference pair at ℓ in the model
// section (a helical pair: the sections ℓ ± b·tan β_b/2; a spur pair: gear_pairs_in_contact),
// the same rule as the scene's contact_pairs.
std::vector<int> gear_pairs_across_face(const kinematics::GearPairGeometry& pair, double position);
// The point ℓ (m from T1) of the line of action in the scene frame (m; pinion centre at the
// origin): where a pair at ℓ touches.
Eigen::Vector2d line_of_action_point(const kinematics::GearPairGeometry& pair, double position);

// The pairs j in contact at ℓ (m from T1, reference pair 0) whose loaded flanks both exist at
// their contact point (issue 31: a broken or chipped faulty tooth drops its pair); empty: the
// mesh has lost contact there. Checks the modifications as write_gear_pair_scene does.
std::vector<int> carrying_gear_pairs(const GearPairSceneSpec& spec, double position);

// The scene's numbers for reports (key, SI value, unit, description).
std::vector<SceneQuantity> scene_quantities(const GearPairScene& scene);

// Parses "sector" or "full" (InputError naming `parameter` otherwise).
RimModel parse_rim_model(const std::string& text, const std::string& parameter);
// Parses "single", "double" or "roll angle" (InputError naming `parameter` otherwise).
PairPosition parse_pair_position(const std::string& text, const std::string& parameter);
// The parameter-file word of a position ("single", "double", "roll angle").
std::string to_string(PairPosition position);
} // namespace gearstiff::geometry
