// Involute gear pair geometry (spur and helical, external and internal) after ISO 21771 /
// DIN 3960, and the single- and double-contact zones along the line of action that the geometry,
// dynamics and stiffness modules build on.
//
// Conventions (the same as geometry/involute_tooth.h):
//  - tooth counts are positive, `internal` marks a ring gear; inside the formulas an internal gear
//    takes the DIN 3960 signs (negative z, d, d_b, d_a), so one set of formulas serves both;
//  - profile shift x > 0 thickens the tooth for external and internal gears alike;
//  - "pinion" (gear 1) drives, it is always external; the "wheel" (gear 2) may be internal;
//  - all lengths in m, angles in rad, everything in the transverse plane unless named normal.
//
// Positions along the line of action are measured in the transverse plane from T1, the point
// where the line of action touches the pinion base circle, towards the pitch point. A point at
// distance ℓ from T1 is touched by the pinion involute when the pinion has rolled ℓ / r_b1
// (its roll angle), which is how the geometry module places contact positions.
#pragma once

#include <string>
#include <vector>

namespace gearstiff::kinematics
{
// One gear of a pair. Every member carries its unit.
struct GearSpec
{
  unsigned int teeth = 0;     // -, number of teeth, positive also for internal gears
  double normal_module = 0.;  // m, m_n
  double pressure_angle = 0.; // rad, normal pressure angle α_n of the basic rack
  double helix_angle = 0.;    // rad, β at the reference circle, 0 for spur gears
  double profile_shift = 0.;  // -, x (DIN 3960: > 0 thickens the tooth)
  double face_width = 0.;     // m, b
  double tip_diameter = 0.;   // m, d_a; 0: standard d ± 2·m_n·(h_aP* + x)
  // m, ρ_a: the tip edge rounded by a circular arc of this radius in the transverse section,
  // tangent to the flank and to the tip circle; 0 = the sharp edge. The flank then ends at the
  // tip form diameter d_Fa (tip_form_diameter below), which bounds the path of contact.
  double tip_rounding_radius = 0.;
  bool internal = false; // ring gear (teeth on the inside)

  // Basic rack profile (ISO 53 profile A), coefficients of m_n.
  double addendum_coefficient = 1.0;     // -, h_aP* (standard tip diameter only)
  double dedendum_coefficient = 1.25;    // -, h_fP*: root diameter d ∓ 2·m_n·(h_fP* − x)
  double root_radius_coefficient = 0.38; // -, ρ_fP*: tip round of the generating rack

  // Blank, for ISO 6336-1 C_R and for the FE model (0: not given / solid).
  double bore_diameter = 0.; // m, inner diameter of the gear body (internal: outer)
  double web_thickness = 0.; // m, b_s; 0 = solid blank (C_R = 1)
  double rim_thickness = 0.; // m, s_R, rim under the root circle (webbed blanks)
};

struct GearPairSpec
{
  GearSpec pinion; // gear 1, external, drives
  GearSpec wheel;  // gear 2, external or internal
  // m, working centre distance; 0: the zero-backlash distance that follows from the profile
  // shifts. Given, it fixes α_wt and the shifts then set the backlash (negative: rejected).
  double centre_distance = 0.;
};

// One stretch of the path of contact with a constant number of tooth pairs in contact.
struct ContactZone
{
  double start = 0.;            // m, along the line of action from T1
  double end = 0.;              // m
  unsigned int pairs = 0;       // -, tooth pairs in contact
  double pinion_roll_start = 0; // rad, pinion roll angle ℓ / r_b1 at `start`
  double pinion_roll_end = 0;   // rad
};

// Per-gear derived quantities (magnitudes, positive also for internal gears).
struct GearGeometry
{
  double reference_diameter = 0.;   // m, d = z·m_t
  double base_diameter = 0.;        // m, d_b
  double tip_diameter = 0.;         // m, d_a actually used
  double tip_form_diameter = 0.;    // m, d_Fa: where the flank meets the tip rounding (sharp: d_a)
  double root_diameter = 0.;        // m, d_f
  double working_diameter = 0.;     // m, d_w (rolling circle of the pair)
  double form_diameter = 0.;        // m, d_Ff: where the generated involute ends at the root
  double active_profile_start = 0.; // m, d_Nf: start of the active profile (mate's tip)
  double tooth_thickness = 0.;      // m, transverse arc thickness on the reference circle
  double tip_thickness = 0.;        // m, normal tooth thickness at the tip circle s_an
  double minimum_profile_shift = 0; // -, x below which the rack undercuts the involute
  double tip_pressure_angle = 0.;   // rad, α_at
};

struct GearPairGeometry
{
  GearPairSpec spec; // the input, with standard tip diameters filled in

  GearGeometry pinion;
  GearGeometry wheel;

  double gear_ratio = 0.;                 // -, u = z2 / z1 (positive; internal: also)
  double transverse_module = 0.;          // m, m_t = m_n / cos β
  double transverse_pressure_angle = 0.;  // rad, α_t
  double working_pressure_angle = 0.;     // rad, α_wt (transverse), from inv α_wt
  double base_helix_angle = 0.;           // rad, β_b
  double centre_distance = 0.;            // m, a_w (magnitude)
  double reference_centre_distance = 0.;  // m, a = m_t·(z2 ± z1)/2
  double backlash = 0.;                   // m, normal backlash j_bn along the line of action
  double transverse_base_pitch = 0.;      // m, p_bt = p_et = π·m_t·cos α_t
  double normal_base_pitch = 0.;          // m, p_bn
  double line_of_action_length = 0.;      // m, T1T2 = a_w·sin α_wt
  double pitch_point = 0.;                // m, C along the line of action from T1
  double contact_start = 0.;              // m, A (wheel's tip form circle d_Fa2, pinion root side)
  double contact_end = 0.;                // m, E (pinion's tip form circle d_Fa1)
  double path_of_contact = 0.;            // m, g_α = AE
  double transverse_contact_ratio = 0.;   // -, ε_α = g_α / p_bt
  double overlap_ratio = 0.;              // -, ε_β = b·sin β / (π·m_n), b common width
  double total_contact_ratio = 0.;        // -, ε_γ
  double common_face_width = 0.;          // m, min(b1, b2)
  double tip_clearance_pinion = 0.;       // m, pinion tip to wheel root (radial)
  double tip_clearance_wheel = 0.;        // m, wheel tip to pinion root (radial)
  std::vector<ContactZone> contact_zones; // from A to E
  std::vector<std::string> warnings;      // legal but unusual (thin tips, small clearance)

  // Number of tooth pairs in contact at `position` (m from T1); 0 outside the path AE.
  unsigned int pairs_in_contact(double position) const;
  // Pinion roll angle at which its involute touches `position`: ℓ / r_b1, in rad.
  double pinion_roll_angle(double position) const;
  // The single-contact zone [B, D] (empty when ε_α ≥ 2).
  double single_contact_start() const; // m, B = E − p_bt
  double single_contact_end() const;   // m, D = A + p_bt
};

// The field (kinematics/fields.h) of a per-gear key written the user's way ("tip diameter",
// "module"): field::gear(wheel, "tip_diameter"). For the callers in geometry/ and stiffness/
// that still name a gear's field by its key; kinematics/ names its fields directly.
std::string gear_parameter_name(bool wheel, const std::string& key);

// Checks the pair and derives every quantity above. Throws InputError (naming the parameter)
// for: non-positive teeth/module/width, an angle out of range, an internal wheel not larger
// than its pinion, an external pinion marked internal, a profile shift that undercuts the
// involute or points the tooth (s_an ≤ 0), a tip inside the base circle, involute interference
// (a tip reaching below the mate's form circle), negative backlash or tip clearance, and
// ε_α < 1. Cost: a few microseconds (one Newton solve for inv α_wt).
GearPairGeometry compute_gear_pair(const GearPairSpec& spec);

// The ring tip designers choose for an internal pair whose standard ring tip interferes with
// the pinion's fillet: the smallest ring tip diameter (the longest ring teeth) for which the
// pair is valid (compute_gear_pair accepts it) and the ring tip meets the pinion at least
// `margin` (m, along the line of action) above the pinion's form circle. InputError naming
// "Gear pair/Wheel/tip diameter" when no ring tip between the base and reference circles
// qualifies. Cost: about 60 pair evaluations (sub-millisecond).
double clearing_ring_tip_diameter(const GearPairSpec& spec, double margin);

// The tip form diameter d_Fa (ISO 21771) of a tip edge rounded with radius ρ_a in the transverse
// section (magnitudes, m; internal: the ring's tip circle is the inner one). The arc's centre lies
// on the involute's normal at the tangency point, a tangent of the base circle, at roll distance
// ρ_Fa − σ·ρ_a from its tangent point and at radius r_a − σ·ρ_a (tangent to the tip circle), so
//   ρ_Fa = σ·ρ_a + √((r_a − σ·ρ_a)² − r_b²),   d_Fa = 2·√(r_b² + ρ_Fa²),
// σ = +1 external, −1 internal. ρ_a = 0 gives d_a. ISO 6336-1 bounds the path of contact by this
// active tip diameter for a rounded or chamfered tip (docs/references.md §20). The arc's centre,
// and so the end of the top land, lies at the half-angle s_t/d + σ·(inv α_t − inv α_C) − ρ_a/r_b
// from the tooth axis, α_C the pressure angle at radius r_a − σ·ρ_a.
double tip_form_diameter(double base_diameter, double tip_diameter, double rounding_radius,
                         bool internal);

// inv(α) = tan α − α and its inverse (Newton, |error| < 1e-14 rad for α in (0, 1.5)).
double involute(double angle);
double inverse_involute(double value);

// The built-in case of docs/references.md §1 (Reszuta & Drewniak 2015): z 21/57, m_n 2.5 mm, 20°,
// x ±0.29, b 26/24 mm, spur. The paper's ε_α = 1.500 (g_α = 1.5·p_et) cannot come from
// standard tips (they give ε_α ≈ 1.618); both tip radii are reduced by the same amount,
// solved so that ε_α = 1.500 exactly. Bores (not published): pinion 20 mm, wheel 40 mm.
GearPairSpec split_path_pair();

// What Reszuta & Drewniak 2015 report for that pair from their ANSYS model (docs/references.md §1,
// printed in N/mm and rad): the one place these reference values live.
namespace split_path_published
{
constexpr double single_pair_stiffness = 327.222e6; // N/m, k'_j = 327 222 N/mm
constexpr double double_pair_stiffness = 497.521e6; // N/m, k'_d = 497 521 N/mm
constexpr double single_pair_rotation = 2.481e-4;   // rad, Δφ of the single-pair position
constexpr double tooth_friction = 0.01;             // -, μ between the teeth of the model
inline const std::string source = "docs/references.md §1 (Reszuta & Drewniak 2015, ANSYS)";
} // namespace split_path_published
} // namespace gearstiff::kinematics
