// The modification stage of a tooth outline: a modelled tooth is its gear's nominal outline
// (geometry/involute_tooth.h) with an ordered list of modifications applied to it. The scene asks
// a ToothProfiles provider (geometry/tooth_profiles.h) for each modelled tooth by its index; a
// tooth without modifications is the nominal outline itself (the same points, bit for bit).
//
// Profile modifications (ISO 21771 terms, docs/references.md §8): material removed normal to the
// involute flank, as a function of the roll length ρ = √(r² − r_b²) of the flank point (the
// position along the path of contact on that gear). A point of a flank moves by δ(ρ) along its
// inward normal; the normal turns by −dδ/ds. Amounts are micrometres over millimetres, so the
// outline keeps its sampling and only the start of a relief (a kink for the linear shape) gets a
// point of its own and starts a new outline piece (ProfileSegment::relief, root_relief).
//
// A rounded tip edge (InvoluteToothSpec::tip_rounding_radius, ProfileSegment::tip_round): the
// flank ends at the tip form circle d_Fa, from which tip reliefs are measured (FlankRollRange::
// tip), so a relief always starts below the arc; the arc moves with the flank point it meets,
// along that point's normal, like a sharp tip corner.
//
// Kinds (more are added as further enumerators with their own apply step, e.g. the tooth faults
// of issue 31: a root crack, a spall, a chipped or broken tooth):
//  - tip relief C_a over the length L_a measured from the tip (roll length), shape linear,
//    parabolic or arc: δ = C_a·f(u), u = 1 − d/L_a, d the roll distance from the tip;
//  - root relief C_f over L_f measured from the root form circle, the same shapes;
//  - profile crowning C_α: δ = C_α·(2(ρ − ρ_m)/L_α)² over the active profile [ρ_A, ρ_E] of the
//    gear (middle ρ_m, length L_α), continued as that parabola beyond it;
//  - profile slope f_Hα: δ = f_Hα·(ρ − ρ_root)/L_α for f_Hα > 0 (removed at the tip), and
//    |f_Hα|·(ρ_tip − ρ)/L_α for f_Hα < 0 (removed at the root): material is only ever removed.
#pragma once

#include "geometry/tooth_profile.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::geometry
{
enum class ModificationKind
{
  tip_relief,
  root_relief,
  profile_crowning,
  profile_slope,
  // Tooth faults (geometry/tooth_fault.h): per tooth, in GearModifications::by_tooth.
  tip_chipping, // amount: height removed from the tip (m), width: a corner (3D)
  broken_tooth, // the tooth removed down to the root circle
  spall,        // amount: depth (m), length: along the loaded flank (m), position: centre
  root_crack    // amount: depth (m), angle, position: start (m radius; 0: critical section)
};

enum class ReliefShape
{
  linear,    // δ = C·u (a kink at the start)
  parabolic, // δ = C·u² (tangent to the flank at the start)
  arc        // a circular arc tangent to the flank at the start through C at the end
};

enum class ModifiedFlanks
{
  loaded, // the flank that carries the load (tooth_profile.h side of scene_gear_pair.h)
  both
};

struct ToothModification
{
  ModificationKind kind = ModificationKind::tip_relief;
  double amount = 0.; // m, removed normal to the flank at the tip/root end (slope: signed)
  double length = 0.; // m, roll length of a relief from the tip / root form (reliefs only)
  ReliefShape shape = ReliefShape::linear;
  ModifiedFlanks flanks = ModifiedFlanks::both;
  // Tooth faults only (geometry/tooth_fault.h):
  // spall: roll angle ξ = ρ/r_b of its centre on the loaded flank (rad; 0: the reference
  // circle); crack: radius of its start on the loaded fillet (m; 0: the 30° critical section)
  double position = 0.;
  double angle = 0.; // rad, crack: angle of the crack path to the tooth centre line
  // m, extent across the face (0: through the face; partial only in 3D): spall: centred on the
  // face's middle; tip chipping: a corner from the end face z = 0
  double width = 0.;
  double width_fraction = 1.;   // -, crack: share of the face from z = 0 (1: through; 3D)
  bool parabolic_front = false; // crack (3D, partial): a parabolic front, else straight
  // crack: true = its faces meet along the path and may close (frictionless contact between
  // them, 2D meshes only); false = an open slit crack_opening wide whose faces never touch
  bool crack_contact = false;
  double crack_tip_size = 0.; // m, crack: cell size at its tip (0: crack_tip_size)
};

// Where a gear's flank meets its mate, as roll lengths ρ on this gear's involute (m).
struct FlankRollRange
{
  double tip = 0.;         // ρ at the flank's tip end: the tip (form) circle, d_Fa when rounded
  double form = 0.;        // ρ at the form circle (start of the involute)
  double active_tip = 0.;  // ρ of the active profile's end nearer the tip
  double active_root = 0.; // ρ of the active profile's end nearer the root
  double single_tip = 0.;  // ρ where single-tooth contact starts/ends on the tip side
  double single_root = 0.; // ρ of the single-contact end on the root side
};

// Lead modifications of a gear (3D scenes only; the shapes and how the mesh carries them:
// geometry/tooth_modification_lead.h), the same on every tooth. All 0: none.
struct LeadModification
{
  double crowning = 0.;          // m, C_β, removed at both ends of the face, 0 in its middle
  double slope = 0.;             // m, f_Hβ; > 0 removes at z = b, < 0 at z = 0
  double end_relief = 0.;        // m, C_I = C_II at both ends of the face
  double end_relief_length = 0.; // m, L_I from each end
  ModifiedFlanks flanks = ModifiedFlanks::both;
  bool empty() const { return crowning == 0. && slope == 0. && end_relief == 0.; }
};

// The modifications of one gear: every tooth gets `all_teeth`, then the list of its index in
// `by_tooth` (tooth indices in the gear's own frame, tooth 0 the reference tooth of the scene),
// and the lead modifications `lead` (3D).
struct GearModifications
{
  std::vector<ToothModification> all_teeth;
  std::map<int, std::vector<ToothModification>> by_tooth;
  LeadModification lead;
  bool empty() const;
};

// Depth removed (m) by the modifications at roll length `roll` on a flank (`loaded` says which
// flank: modifications with ModifiedFlanks::loaded skip the other one).
double removed_depth(const std::vector<ToothModification>& modifications,
                     const FlankRollRange& range, double roll, bool loaded);

// The two loaded flanks of a tooth pair as its touching point sees them (touching_separation):
// each gear's removed depth by roll length (modifications and flank faults) and the rolls its
// flank covers, the base radii and T2 on the line of action.
struct PairFlanks
{
  std::function<double(double)> pinion_removal; // m, removed depth at the pinion's roll (m)
  std::function<double(double)> wheel_removal;  // m, at the wheel's roll (m)
  FlankRollRange pinion_range, wheel_range;
  double pinion_base_radius = 0.; // m, r_b1
  double wheel_base_radius = 0.;  // m, r_b2
  double t2 = 0.;                 // m, T2 from T1 along the line of action (a ring's: negative)
  bool internal = false;          // the wheel is a ring: its flank concave
};

// The designed separation of a pair whose unmodified flanks touch at ℓ = `at` on the line of
// action (m from T1; the pinion's roll ℓ, the wheel's |ℓ − t2|): the smallest gap between the
// modified flanks near that point, not their removal at it. A tangential offset x moves gear i's
// point by x·r_bi/ρ_i of roll (the involute's arc length is ρ²/(2r_b)) and parts the unmodified
// flanks by x²/(2R) (R the relative radius; a ring's flank is concave), so the gap is
// g(x) = x²/(2R) + S₁(ℓ + x·r_b1/ρ₁) + S₂(ℓ + x·r_b2/ρ₂) in ℓ's terms, and rigid flanks first
// touch where it is smallest: a relief's slope β moves that point by βR and lowers the gap by
// β²R/2 (docs/ltca.md §5 "Where modified flanks touch"). Offsets where either flank ends are
// not searched (a tip corner is not a flank point).
struct FlankTouch
{
  double separation = 0.; // m, the smallest gap
  double offset = 0.;     // m, x where it lies
};
FlankTouch touching_point(const PairFlanks& flanks, double at);
inline double touching_separation(const PairFlanks& flanks, double at)
{
  return touching_point(flanks, at).separation;
}

// The nominal outline with the modifications applied to its flanks (side `loaded_side` is the
// loaded flank). `parameter` is the gear whose fields an InputError names
// (geometry::field::modified_gear: "pinion.tip_relief_length", geometry/fields.h) for a
// modification that does not fit the tooth: a relief longer than the active profile, a negative
// amount, removal that reaches the tooth thickness.
ToothProfile modified_tooth(const ToothProfile& nominal,
                            const std::vector<ToothModification>& modifications,
                            const FlankRollRange& range, int loaded_side,
                            const std::string& parameter);

// The checks of modified_tooth without building (InputError naming
// field::gear_entry(parameter, "tip relief") etc.).
void check_modifications(const std::vector<ToothModification>& modifications,
                         const ToothProfile& nominal, const FlankRollRange& range,
                         const std::string& parameter);

// The fault kinds (geometry/tooth_fault.h models them): chipping, broken tooth, spall, crack.
bool is_fault(ModificationKind kind);
bool has_faults(const std::vector<ToothModification>& modifications);
// The parameter word of a fault's size ("tip chipping", "broken tooth", "spall depth",
// "crack depth").
std::string fault_name(ModificationKind kind);

// Parameter-file words: "linear|parabolic|arc", "loaded|both" (InputError naming `parameter`).
ReliefShape parse_relief_shape(const std::string& text, const std::string& parameter);
ModifiedFlanks parse_modified_flanks(const std::string& text, const std::string& parameter);
} // namespace gearstiff::geometry
