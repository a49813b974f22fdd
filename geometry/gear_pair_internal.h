// Internal to geometry/: what the files of the gear-pair scene share —
// gear_pair_bodies.cc (the teeth, rims and bodies of both gears), gear_pair_placement.cc (where
// the reference pair touches, which pairs are in contact, the gears placed in mesh, the teeth
// modelled), gear_pair_contacts.cc (predicted contacts, contact lines across the face, the
// designed separations) and scene_gear_pair.cc (the scene written: face-width stage, mesh).
// Included by those files only.
#pragma once

#include "geometry/mesh_planar.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_profiles.h"

#include <Eigen/Core>
#include <map>
#include <vector>

namespace gearstiff::geometry::detail
{
// Contacts closer than this to the ends A, E of the path of contact still count (m): the
// zone ends come from the same floating-point formulas as the positions.
inline constexpr double path_tolerance = 1e-9;

// The line of action (header comment): T1 on the pinion base circle, direction u.
struct LineOfAction
{
  Eigen::Vector2d t1, u;
  double t2; // m, T2 from T1 (internal pair: behind T1, negative)
  Eigen::Vector2d at(double position) const { return t1 + position * u; }
};

// The placed teeth: profiles, centres and the rotations that put pair 0 at the reference.
struct PlacedGears
{
  ToothProfile pinion, wheel;              // nominal outlines (placement)
  ToothProfiles pinion_teeth, wheel_teeth; // every modelled tooth, modified or nominal
  // The flanks the contacts touch: the teeth without their partial-width faults (3D: a partial
  // spall or chipped corner leaves the flank whole over the rest of the face).
  ToothProfiles pinion_contact_teeth, wheel_contact_teeth;
  Eigen::Vector2d pinion_centre, wheel_centre;
  double pinion_rotation = 0., wheel_rotation = 0.;
};

// The teeth in the scene: windows of pair indices centred on the contacting pairs.
struct ModelWindows
{
  int pinion_first = 0, pinion_last = 0;         // pinion tooth indices
  int wheel_first_pair = 0, wheel_last_pair = 0; // pair indices j of the wheel's teeth
  int wheel_first = 0, wheel_last = 0;           // wheel tooth indices (its own frame)
};

// gear_pair_bodies.cc
double outline_root_radius(const ToothProfile& tooth);
bool is_flank(ProfileSegment segment);
int loaded_side(const ToothProfile& tooth);
double involute_sign(const ToothProfile& tooth);
void check_scene_spec(const GearPairSceneSpec& spec);
PlacedGears generate_teeth(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair);
void set_rims(const GearPairSceneSpec& spec, const PlacedGears& gears, GearPairScene& scene);
PlanarModel gear_pair_model(const GearPairSceneSpec& spec, const PlacedGears& gears,
                            const GearPairScene& scene, const ModelWindows& w, double face_width);
std::vector<SizeFocus> placed_fault_foci(const ToothProfiles& teeth, const Eigen::Vector2d& centre,
                                         double rotation, int first, int last);

// gear_pair_placement.cc
Eigen::Vector2d place(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double rotation);
double reference_position(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair);
std::vector<int> pairs_in_contact(const kinematics::GearPairGeometry& pair, double reference);
LineOfAction line_of_action(const kinematics::GearPairGeometry& pair);
int mate_tooth(const ToothProfile& wheel, int j);
void locate_pairs(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                  const LineOfAction& line, const PlacedGears& gears, GearPairScene& scene);
// m, the wheel's centre in the scene frame (the pinion's is the origin): on the x axis, beyond
// the pitch point (external) or behind the pinion's centre (ring).
Eigen::Vector2d wheel_centre(const kinematics::GearPairGeometry& pair);
void place_gears(const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                 double reference, PlacedGears& gears);
ModelWindows model_windows(const GearPairSceneSpec& spec, const PlacedGears& gears,
                           GearPairScene& scene);

// gear_pair_contacts.cc
SceneContact predicted_contact(const GearPairSceneSpec& spec,
                               const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                               const PlacedGears& gears, double reference, int j,
                               double normal_force, double roll = 0.);
void add_swept_contacts(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                        const LineOfAction& line, const PlacedGears& gears, double reference,
                        std::vector<SceneContact>& contacts);
void add_tip_round_contacts(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                            const PlacedGears& gears, double first, double last,
                            std::vector<SceneContact>& contacts);
void set_unloaded_transmission_error(const GearPairSceneSpec& spec,
                                     const kinematics::GearPairGeometry& pair,
                                     const LineOfAction& line, const PlacedGears& gears,
                                     GearPairScene& scene);

// gear_pair_helix.cc (β = 0: a spur pair, every function the identity of the spur scene)
void check_helical_scene(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair);
bool is_helical_pair(const kinematics::GearPairGeometry& pair);
// -, dℓ/dz: how far the transverse contact moves along the line of action per metre of face
// (σ·tan β_b, σ the pinion's hand); 0 for spur.
double contact_shift_rate(const kinematics::GearPairGeometry& pair);
// m, z of the section that is the transverse model (the middle of the face).
double model_section(const kinematics::GearPairGeometry& pair);
// m, the positions ℓ the sections across the face meet with the model section at `reference`
// (reference ± b·tan β_b/2), sampled every quarter base pitch, also beyond the path of contact.
std::vector<double> face_positions(const kinematics::GearPairGeometry& pair, double reference);
// The pairs j in contact in some section across the face.
std::vector<int> pairs_across_face(const kinematics::GearPairGeometry& pair, double reference);
// m, the roll from the model section to the section where pair j lies nearest to `reference`
// inside the path of contact (0 when it is in contact there).
double nearest_roll(const kinematics::GearPairGeometry& pair, double reference, int j);
std::vector<ContactLine> contact_lines(const kinematics::GearPairGeometry& pair,
                                       const LineOfAction& line, double reference,
                                       const std::vector<int>& pairs);
} // namespace gearstiff::geometry::detail
