// Involute spur-gear teeth generated as they are cut: the outline is the envelope of a cutter in
// the generating motion, so the root fillet is the exact trochoidal envelope of the cutter tip
// round (not an arc), the flank is the involute of the base circle, and undercut appears by itself
// where the tip round cuts into the involute.
//
// Profile-shift convention (DIN 3960 / ISO 21771): positive x thickens the tooth, for external and
// internal gears alike, so the tooth thickness on the reference circle is
// s = m·(π/2 + 2·x·tan α) for both; for an internal gear positive x moves the profile towards the
// gear axis.
#pragma once

#include "geometry/tooth_profile.h"
#include "kinematics/gear_pair.h"

namespace gearstiff::geometry
{
enum class TipReliefShape
{
  linear,   // removed depth proportional to the roll length past the start (kink at the start)
  parabolic // proportional to its square (tangent-continuous at the start)
};

struct InvoluteToothSpec
{
  unsigned int teeth = 0;     // number of teeth (positive also for internal gears), ≥ 3
  double module = 0.;         // m, transverse module (spur gears: = normal module)
  double pressure_angle = 0.; // rad, reference (cutter) pressure angle, 0 < α < 45°
  double profile_shift = 0.;  // -, coefficient x (convention above)
  // m, tip-circle diameter; 0 selects the standard d ± 2·m·(h_aP ± x) (see tip_diameter()).
  double tip_diameter = 0.;
  bool internal = false; // ring gear

  // Cutter (basic rack profile ISO 53 A by default), coefficients of the module:
  double cutter_addendum = 1.25;   // -, h_a0/m: cuts the gear dedendum (root circle)
  double cutter_dedendum = 1.0;    // -, h_f0/m: the tip may not reach deeper into the cutter
  double cutter_tip_radius = 0.38; // -, ρ_a0/m, radius of the rounded cutter tip
  double gear_addendum = 1.0;      // -, h_aP/m, for the standard tip diameter only
  // 0: rack cutter (hob / rack); for internal gears this is the rack-equivalent
  // simplification (see involute_tooth.cc). > 0: pinion-type (shaper) cutter with that many
  // teeth and profile shift cutter_profile_shift (internal gears: the real process).
  unsigned int cutter_teeth = 0;
  double cutter_profile_shift = 0.; // -, x0 of the pinion-type cutter

  // Tip relief (0 amount: none): depth removed normal to the involute at the tip circle.
  double tip_relief_amount = 0.;         // m
  double tip_relief_start_diameter = 0.; // m, where the relief starts (between form and tip)
  TipReliefShape tip_relief_shape = TipReliefShape::linear;

  // m, ρ_a: the tip edge rounded by a circular arc of this radius (in this transverse section)
  // tangent to the flank (the involute, or the relieved flank where the tip relief reaches) and
  // to the tip circle, on both flanks; 0 = the sharp edge. The flank meets the arc at the tip
  // form circle d_Fa (ToothProfile::tip_form_radius; kinematics::tip_form_diameter without tip
  // relief). Refused (InputError) when the arc would consume the whole top land or reach below
  // the tip relief's start or the form circle.
  double tip_rounding_radius = 0.;

  // m, the involute must reach down to (external) / up to (internal) this diameter, usually
  // the start of the active profile given by the mating gear; an undercut or fillet that
  // eats into it is rejected. 0: only reject undercut that leaves no involute at all.
  double required_form_diameter = 0.;
};

// The tip diameter actually used: spec.tip_diameter or the standard one, in m.
double tip_diameter(const InvoluteToothSpec& spec);

// The tooth of one gear of kinematics' pair; a helical gear's transverse tooth (m_t, α_t,
// x·m_n, the transverse section of its rack: involute_tooth.cc). The cutter is the gear's basic
// rack (addendum h_fP*, dedendum h_aP*, tip round ρ_fP*); tip diameter as the pair uses it, and
// its tip rounding radius (transverse, as GearSpec gives it).
// `required_form_diameter` is left 0 (kinematics checks the form circle against its mate).
InvoluteToothSpec involute_tooth_spec(const kinematics::GearSpec& gear, double tip_diameter);

// inv(α) = tan α − α.
double involute_function(double angle);

// Checks the spec (InputError naming the parameter: pointed tooth, undercut reaching the
// required form diameter, cutter tip round that does not fit, tip beyond the cutter dedendum)
// and generates one tooth. Cost: microseconds to a millisecond.
ToothProfile generate_involute_tooth(const InvoluteToothSpec& spec,
                                     const ProfileResolution& resolution = ProfileResolution());

// generate_involute_tooth for the pinion's (wheel = false) or wheel's tooth: the generator
// knows one tooth, not which gear, so its fields ("tooth.tip_diameter", geometry/fields.h) are
// named as the gear's own ("wheel.tip_diameter", kinematics/fields.h), the name the
// kinematics' checks of the same gear use.
ToothProfile generate_gear_tooth(const InvoluteToothSpec& spec, const ProfileResolution& resolution,
                                 bool wheel);
} // namespace gearstiff::geometry
