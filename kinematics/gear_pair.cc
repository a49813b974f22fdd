#include "kinematics/gear_pair.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "kinematics/fields.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace gearstiff::kinematics
{
namespace
{
constexpr double pi = 3.14159265358979323846;

std::string millimetres(double metres)
{
  return format_number(metres * 1e3, 4) + " mm";
}

void check_gear(const GearSpec& gear, bool wheel)
{
  auto name = [&](const std::string& member) { return field::gear(wheel, member); };
  if (gear.teeth < 3)
    throw InputError(name("teeth"), "must be at least 3, got " + std::to_string(gear.teeth));
  if (!(gear.normal_module > 0.))
    throw InputError(name("normal_module"), "must be positive");
  if (!(gear.pressure_angle > 0. && gear.pressure_angle < 0.5 * pi / 2.))
    throw InputError(name("pressure_angle"), "must lie in (0°, 45°)");
  if (!(std::abs(gear.helix_angle) < pi / 3.))
    throw InputError(name("helix_angle"), "must lie in (−60°, 60°)");
  if (!(gear.face_width > 0.))
    throw InputError(name("face_width"), "must be positive");
  if (!(gear.tip_diameter >= 0.))
    throw InputError(name("tip_diameter"), "must be 0 (standard) or positive");
  if (!(gear.tip_rounding_radius >= 0.) || !std::isfinite(gear.tip_rounding_radius))
    throw InputError(name("tip_rounding_radius"), "must be 0 (sharp) or positive (mm)");
  if (!(gear.addendum_coefficient > 0.) || !(gear.dedendum_coefficient > 0.) ||
      !(gear.root_radius_coefficient >= 0.))
    throw InputError(name("dedendum_coefficient"), "basic rack coefficients must be positive");
  if (!(gear.dedendum_coefficient >
        gear.root_radius_coefficient * (1. - std::sin(gear.pressure_angle))))
    throw InputError(name("root_radius_coefficient"),
                     "the rack tip round does not fit into the rack dedendum");
  // The generating rack's tooth is π·m/2 wide on its datum line and narrows by tan α on each
  // side over its addendum (the gear's dedendum): its two tip rounds must not overlap. In the
  // transverse section the geometry module cuts (m_t, α_t, the depths and ρ in metres as in the
  // normal section), so the check is that of geometry::rack_motion, here at parse time in the
  // user's coefficients (α_n 25° with the ISO 53 rack's h_fP* 1.25 and ρ_fP* 0.38 fails it).
  const double c = std::cos(gear.helix_angle);
  const double alpha_t = std::atan(std::tan(gear.pressure_angle) / c);
  const double largest = (pi / (4. * c) - gear.dedendum_coefficient * std::tan(alpha_t)) *
                         std::cos(alpha_t) / (1. - std::sin(alpha_t));
  if (gear.root_radius_coefficient > largest)
    throw InputError(
        name("root_radius_coefficient"),
        format_number(gear.root_radius_coefficient, 4) +
            " is too large for this basic rack: its two tip rounds would overlap (at most " +
            (largest > 0. ? format_number(largest, 4) : std::string("0")) +
            " with pressure angle " + format_number(gear.pressure_angle * 180. / pi, 4) +
            "° and dedendum coefficient " + format_number(gear.dedendum_coefficient, 4) +
            (gear.helix_angle != 0.
                 ? ", helix angle " + format_number(gear.helix_angle * 180. / pi, 4) + "°"
                 : std::string()) +
            ")");
}

// The rack flank generates the involute down to the height where its tip round
// starts; a point at depth h below the rolling line lies h / sin α_t along the
// line of action from the pitch point. Returns the roll length from the gear's
// own tangent point T (m); negative for an external gear means the rack
// undercuts the involute.
double form_roll_length(const GearSpec& gear, double reference_radius,
                        double transverse_pressure_angle)
{
  const double m = gear.normal_module;
  const double straight_flank_depth =
      (gear.dedendum_coefficient -
       gear.root_radius_coefficient * (1. - std::sin(gear.pressure_angle))) *
      m;
  const double side = gear.internal ? -1. : 1.;
  return reference_radius * std::sin(transverse_pressure_angle) -
         side * (straight_flank_depth - gear.profile_shift * m) /
             std::sin(transverse_pressure_angle);
}

// ε_α ≥ 1, naming what shortened the path of contact: a given centre distance
// larger than the zero-backlash one pulls the tips apart (positive backlash),
// otherwise the tips are short.
void check_contact_ratio(const GearPairGeometry& result)
{
  const double ratio = result.transverse_contact_ratio;
  if (ratio >= 1.)
    return;
  const std::string path =
      result.path_of_contact > 0.
          ? "transverse contact ratio ε_α = " + format_number(ratio, 4) + " < 1"
          : "the tips do not reach each other's flanks along the line of "
            "action (no path of "
            "contact)";
  if (result.spec.centre_distance > 0. && result.backlash > 0.)
    throw InputError(field::centre_distance, millimetres(result.centre_distance) +
                                                 " exceeds the zero-backlash distance "
                                                 "(backlash " +
                                                 millimetres(result.backlash) + "): " + path);
  throw InputError(field::gear(false, "tip_diameter"),
                   path + ": the tips are too short for continuous contact");
}

// The body inside the root circle: an external gear's bore must lie inside its
// root circle, an internal gear's outer diameter (bore_diameter) outside it.
void check_bore(const GearSpec& gear, bool wheel, double root_diameter)
{
  // An internal wheel's outer diameter is checked by the FE scene against its rim thickness;
  // the pair's geometry does not depend on it.
  if (gear.bore_diameter == 0. || gear.internal)
    return;
  if (!(gear.bore_diameter > 0.))
    throw InputError(field::gear(wheel, "bore_diameter"), "must be 0 or positive");
  if (gear.internal ? gear.bore_diameter <= root_diameter : gear.bore_diameter >= root_diameter)
    throw InputError(field::gear(wheel, "bore_diameter"),
                     millimetres(gear.bore_diameter) + " lies " +
                         (gear.internal ? "inside" : "outside") + " the root circle " +
                         millimetres(root_diameter) + ": no gear body is left");
}
} // namespace

std::string gear_parameter_name(bool wheel, const std::string& key)
{
  std::string member = key == "module" ? "normal_module" : key;
  std::replace(member.begin(), member.end(), ' ', '_');
  return field::gear(wheel, member);
}

double tip_form_diameter(double base_diameter, double tip_diameter, double rounding_radius,
                         bool internal)
{
  const double sigma = internal ? -1. : 1.;
  const double rb = 0.5 * base_diameter;
  const double centre_radius = 0.5 * tip_diameter - sigma * rounding_radius;
  const double roll =
      sigma * rounding_radius + std::sqrt(std::max(0., centre_radius * centre_radius - rb * rb));
  return 2. * std::sqrt(rb * rb + roll * roll);
}

double involute(double angle)
{
  return std::tan(angle) - angle;
}

double inverse_involute(double value)
{
  if (!(value >= 0.) || !(value < 10.))
    throw SolverFailure("inverse involute",
                        "argument " + format_number(value, 4) + " out of range");
  // inv α ≈ α³/3 near 0 gives a start on the convex side, from which Newton
  // converges monotonically (inv is convex on [0, π/2)).
  double angle = std::min(std::cbrt(3. * value), 1.5);
  for (unsigned int iteration = 0; iteration < 60; ++iteration)
  {
    const double tangent = std::tan(angle);
    const double step = (tangent - angle - value) / (tangent * tangent);
    angle -= step;
    if (std::abs(step) < 1e-15)
      return angle;
  }
  throw SolverFailure("inverse involute",
                      "Newton iteration did not converge for " + format_number(value, 4));
}

unsigned int GearPairGeometry::pairs_in_contact(double position) const
{
  if (position < contact_start || position > contact_end)
    return 0;
  const double p = transverse_base_pitch;
  return static_cast<unsigned int>(std::floor((contact_end - position) / p) +
                                   std::floor((position - contact_start) / p) + 1.);
}

double GearPairGeometry::pinion_roll_angle(double position) const
{
  return position / (0.5 * pinion.base_diameter);
}

double GearPairGeometry::single_contact_start() const
{
  return contact_end - transverse_base_pitch;
}

double GearPairGeometry::single_contact_end() const
{
  return contact_start + transverse_base_pitch;
}

namespace
{
void check_pair_spec(const GearPairSpec& spec)
{
  check_gear(spec.pinion, false);
  check_gear(spec.wheel, true);
  if (spec.pinion.internal)
    throw InputError(field::gear(false, "internal"),
                     "the pinion must be external (make the wheel the ring gear)");
  const GearSpec& g1 = spec.pinion;
  const GearSpec& g2 = spec.wheel;
  if (g1.normal_module != g2.normal_module)
    throw InputError(field::gear(true, "normal_module"),
                     "differs from the pinion's: meshing gears share the normal module");
  if (g1.pressure_angle != g2.pressure_angle)
    throw InputError(field::gear(true, "pressure_angle"),
                     "differs from the pinion's: meshing gears share the basic rack");
  // Meshing external helical gears have opposite hands, internal ones the same
  // hand; the pair is described by the pinion's β, the wheel's must have the
  // same magnitude.
  if (std::abs(std::abs(g1.helix_angle) - std::abs(g2.helix_angle)) > 1e-12)
    throw InputError(field::gear(true, "helix_angle"), "differs in magnitude from the pinion's");
  // The sign is the hand (ISO 21771): β > 0 right hand, β < 0 left hand.
  if (g1.helix_angle != 0. && !g2.internal && (g1.helix_angle > 0.) == (g2.helix_angle > 0.))
    throw InputError(field::gear(true, "helix_angle"),
                     "has the pinion's hand: an external pair meshes with opposite hands (β > 0 "
                     "right hand, β < 0 left hand; give the wheel −β)");
  if (g1.helix_angle != 0. && g2.internal && (g1.helix_angle > 0.) != (g2.helix_angle > 0.))
    throw InputError(field::gear(true, "helix_angle"),
                     "has the other hand than the pinion's: an internal pair meshes with the same "
                     "hand (β > 0 right hand, β < 0 left hand)");
  if (g2.internal && g2.teeth <= g1.teeth)
    throw InputError(field::gear(true, "teeth"),
                     "an internal wheel needs more teeth than its pinion (" +
                         std::to_string(g2.teeth) + " ≤ " + std::to_string(g1.teeth) + ")");
  if (!(spec.centre_distance >= 0.))
    throw InputError(field::centre_distance, "must be 0 (from the shifts) or positive");
}

// The pair's basic quantities with the DIN 3960 signs: the internal wheel has
// negative z and diameters, so one set of formulas serves both kinds of pair.
struct SignedPair
{
  double s2;               // -, +1 external wheel, −1 internal
  double z1, z2;           // -, signed tooth counts
  double m_n, alpha_n;     // m, rad
  double beta;             // rad, |β|
  double m_t, alpha_t;     // m, rad (transverse)
  double d1, d2, db1, db2; // m, reference and base diameters
  double da1, da2;         // m, tip diameters
  double dFa1, dFa2;       // m, tip form diameters (magnitudes; sharp edges: |d_a|)
  double df1, df2;         // m, root diameters
  double x_sum;            // -, x1 + x2
};

SignedPair signed_pair(const GearPairSpec& spec)
{
  const GearSpec& g1 = spec.pinion;
  const GearSpec& g2 = spec.wheel;
  SignedPair p;
  p.s2 = g2.internal ? -1. : 1.;
  p.z1 = g1.teeth;
  p.z2 = p.s2 * g2.teeth;
  p.m_n = g1.normal_module;
  p.alpha_n = g1.pressure_angle;
  p.beta = std::abs(g1.helix_angle);
  p.m_t = p.m_n / std::cos(p.beta);
  p.alpha_t = std::atan(std::tan(p.alpha_n) / std::cos(p.beta));
  p.d1 = p.z1 * p.m_t;
  p.d2 = p.z2 * p.m_t;
  p.db1 = p.d1 * std::cos(p.alpha_t);
  p.db2 = p.d2 * std::cos(p.alpha_t);
  p.x_sum = g1.profile_shift + g2.profile_shift;
  // Tip and root diameters, signed: d ± 2·m_n·(h* ± x) in one formula.
  const auto tip_of = [&](const GearSpec& g, double d, double side)
  {
    return g.tip_diameter > 0. ? side * g.tip_diameter
                               : d + 2. * p.m_n * (g.addendum_coefficient + g.profile_shift);
  };
  const auto root_of = [&](const GearSpec& g, double d)
  { return d - 2. * p.m_n * (g.dedendum_coefficient - g.profile_shift); };
  p.da1 = tip_of(g1, p.d1, 1.);
  p.da2 = tip_of(g2, p.d2, p.s2);
  p.df1 = root_of(g1, p.d1);
  p.df2 = root_of(g2, p.d2);
  p.dFa1 = g1.tip_rounding_radius > 0.
               ? tip_form_diameter(std::abs(p.db1), std::abs(p.da1), g1.tip_rounding_radius, false)
               : std::abs(p.da1);
  p.dFa2 = g2.tip_rounding_radius > 0. ? tip_form_diameter(std::abs(p.db2), std::abs(p.da2),
                                                           g2.tip_rounding_radius, g2.internal)
                                       : std::abs(p.da2);
  return p;
}

// α_wt and the backlash: zero backlash from the shifts, or the given centre
// distance.
void set_working_pressure_angle(const GearPairSpec& spec, const SignedPair& p,
                                GearPairGeometry& result)
{
  // ISO 21771 eq. for the zero-backlash working pressure angle: inv α_wt = inv
  // α_t + 2·tan α_n·(x1 + x2)/(z1 + z2), signed z serving external and internal
  // pairs.
  const double inv_alpha_zero_backlash =
      involute(p.alpha_t) + 2. * std::tan(p.alpha_n) * p.x_sum / (p.z1 + p.z2);
  if (!(inv_alpha_zero_backlash > 0.))
    throw InputError(field::gear(true, "profile_shift"), "x1 + x2 = " + format_number(p.x_sum, 4) +
                                                             " leaves no working pressure angle");
  const double reference_centre_distance = 0.5 * (p.d1 + p.d2);
  result.reference_centre_distance = std::abs(reference_centre_distance);

  double alpha_wt = 0.;
  if (spec.centre_distance == 0.)
  {
    alpha_wt = inverse_involute(inv_alpha_zero_backlash);
    result.backlash = 0.;
  }
  else
  {
    const double cos_alpha_wt =
        std::abs(reference_centre_distance) * std::cos(p.alpha_t) / spec.centre_distance;
    if (!(cos_alpha_wt > 0.2 && cos_alpha_wt < 1.))
      throw InputError(field::centre_distance,
                       millimetres(spec.centre_distance) +
                           " is incompatible with the reference centre distance " +
                           millimetres(std::abs(reference_centre_distance)));
    alpha_wt = std::acos(cos_alpha_wt);
    // Shifts that would close the gap, minus the shifts present, thicken both
    // teeth by 2·Δx·m_n·sin α_n along the normal line of action.
    const double x_sum_zero_backlash =
        (involute(alpha_wt) - involute(p.alpha_t)) * (p.z1 + p.z2) / (2. * std::tan(p.alpha_n));
    result.backlash = 2. * p.m_n * std::sin(p.alpha_n) * (x_sum_zero_backlash - p.x_sum);
    if (result.backlash < -1e-9)
      throw InputError(field::centre_distance,
                       millimetres(spec.centre_distance) +
                           " is too small for the profile shifts (negative backlash " +
                           millimetres(result.backlash) + ")");
  }
  result.working_pressure_angle = alpha_wt;
  const double a_w = 0.5 * (p.db1 + p.db2) / std::cos(alpha_wt); // signed (internal: < 0)
  result.centre_distance = std::abs(a_w);
}

// Each tip between its base and root circles, and each body inside its root
// circle.
void check_tips_and_bores(const GearPairSpec& spec, const SignedPair& p)
{
  for (const bool wheel : {false, true})
  {
    const double da = wheel ? p.da2 : p.da1;
    const double db = wheel ? p.db2 : p.db1;
    const double df = wheel ? p.df2 : p.df1;
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    // An explicit tip below (external) / above (internal) the root circle that
    // the module, teeth and shift give does not belong to this gear at all: the
    // module (or teeth) was changed without the tip, which is what to fix
    // first.
    const bool tip_beyond_root = g.internal ? std::abs(da) >= std::abs(df) : da <= df;
    if (g.tip_diameter > 0. && tip_beyond_root)
      throw InputError(field::gear(wheel, "normal_module"),
                       format_number(g.normal_module * 1e3, 4) + " mm with " +
                           std::to_string(g.teeth) + " teeth puts the root circle at " +
                           millimetres(std::abs(df)) + ", " + (g.internal ? "inside" : "outside") +
                           " the given tip diameter " + millimetres(std::abs(da)) +
                           " (tip diameter auto takes the standard tip of this module)");
    // A tip inside the base circle has no involute to run on.
    if (!(std::abs(da) > std::abs(db)))
      throw InputError(field::gear(wheel, "tip_diameter"), millimetres(std::abs(da)) +
                                                               " is not outside the base circle " +
                                                               millimetres(std::abs(db)));
    if (!(g.internal ? std::abs(da) < std::abs(df) : da > df))
      throw InputError(field::gear(wheel, "tip_diameter"), millimetres(std::abs(da)) +
                                                               " lies beyond the root circle " +
                                                               millimetres(std::abs(df)));
    check_bore(g, wheel, std::abs(df));
  }
}

// Transverse tooth thickness at the reference circle [m] (ISO 21771).
double reference_tooth_thickness(const GearSpec& g, const SignedPair& p)
{
  return p.m_t * (pi / 2. + 2. * g.profile_shift * std::tan(p.alpha_n));
}

// Normal tooth thickness at the tip circle [m]; a gear of its own, before any pair check, so
// that a shift or tip that makes the tooth pointed is named as that, not as the interference
// the same pointed tooth also causes.
double normal_tip_thickness(const GearSpec& g, const SignedPair& p, bool wheel)
{
  const double d = wheel ? p.d2 : p.d1;
  const double db = wheel ? p.db2 : p.db1;
  const double da = wheel ? p.da2 : p.da1;
  const double s_at = da * (reference_tooth_thickness(g, p) / d + involute(p.alpha_t) -
                            involute(std::acos(db / da)));
  const double beta_a = std::atan(std::tan(p.beta) * da / d);
  return s_at * std::cos(beta_a);
}

void check_tip_thickness(const GearPairSpec& spec, const SignedPair& p)
{
  for (const bool wheel : {false, true})
  {
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    const double tip_thickness = normal_tip_thickness(g, p, wheel);
    if (!(tip_thickness > 0.))
      throw InputError(field::gear(wheel, g.tip_diameter > 0. ? "tip_diameter" : "profile_shift"),
                       "the tooth comes to a point before the tip circle (tip thickness " +
                           millimetres(tip_thickness) + ")");
  }
}

// A tip rounding that fits (kinematics/gear_pair.h, tip_form_diameter): its centre outside the
// base circle (external), and a top land left between the two arcs. The form circle is checked
// against d_Fa once the form roll lengths are known (check_rounding_above_form).
void check_tip_rounding(const GearPairSpec& spec, const SignedPair& p)
{
  for (const bool wheel : {false, true})
  {
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    const double rho = g.tip_rounding_radius;
    if (!(rho > 0.))
      continue;
    const double sigma = g.internal ? -1. : 1.;
    const double rb = 0.5 * std::abs(wheel ? p.db2 : p.db1);
    const double ra = 0.5 * std::abs(wheel ? p.da2 : p.da1);
    const double centre_radius = ra - sigma * rho;
    if (!(centre_radius > rb))
      throw InputError(field::gear(wheel, "tip_rounding_radius"),
                       millimetres(rho) + " does not fit: the tip circle lies only " +
                           millimetres(ra - rb) + " outside the base circle");
    // Half-angle of the arc's centre from the tooth axis (header): the top land that is left.
    const auto inv_at = [rb](double r) { return involute(std::acos(rb / r)); };
    const double d = std::abs(wheel ? p.d2 : p.d1);
    const double land_angle = reference_tooth_thickness(g, p) / d +
                              sigma * (involute(p.alpha_t) - inv_at(centre_radius)) - rho / rb;
    if (!(land_angle > 0.))
      throw InputError(field::gear(wheel, "tip_rounding_radius"),
                       millimetres(rho) + " consumes the whole top land (tip diameter " +
                           millimetres(2. * ra) + ")");
  }
}

// d_Fa above (external) / inside (internal) the form circle: the rounding leaves an involute.
void check_rounding_above_form(const GearPairSpec& spec, const SignedPair& p,
                               std::pair<double, double> form_rolls)
{
  for (const bool wheel : {false, true})
  {
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    if (!(g.tip_rounding_radius > 0.))
      continue;
    const double rb = 0.5 * std::abs(wheel ? p.db2 : p.db1);
    const double r_fa = 0.5 * (wheel ? p.dFa2 : p.dFa1);
    const double roll_fa = std::sqrt(std::max(0., r_fa * r_fa - rb * rb));
    const double form = wheel ? form_rolls.second : form_rolls.first;
    if (g.internal ? !(roll_fa < form) : !(roll_fa > form))
      throw InputError(field::gear(wheel, "tip_rounding_radius"),
                       millimetres(g.tip_rounding_radius) +
                           " reaches the form circle: the tip form diameter d_Fa " +
                           millimetres(2. * r_fa) + " leaves no involute above d_Ff " +
                           millimetres(2. * std::sqrt(rb * rb + form * form)));
  }
}

// Line of action from T1 towards the pitch point C (module header): T2, C, A
// and E.
void set_line_of_action(const SignedPair& p, GearPairGeometry& result)
{
  const double rb1 = 0.5 * p.db1;
  const double rb2 = 0.5 * p.db2;
  const double tan_wt = std::tan(result.working_pressure_angle);
  const double t2_position = (rb1 + rb2) * tan_wt;
  result.line_of_action_length = std::abs(t2_position);
  result.pitch_point = rb1 * tan_wt;
  // The active tips are the tip form circles (the tip circles when the edges are sharp).
  const double ra1 = 0.5 * p.dFa1;
  const double ra2 = 0.5 * p.dFa2;
  result.contact_end = std::sqrt(ra1 * ra1 - rb1 * rb1);
  result.contact_start = t2_position - p.s2 * std::sqrt(ra2 * ra2 - rb2 * rb2);
}

// Roll length on the wheel at `position`, measured from its own tangent point
// T2.
double wheel_roll_length(const SignedPair& p, const GearPairGeometry& result, double position)
{
  const double t2_position = 0.5 * (p.db1 + p.db2) * std::tan(result.working_pressure_angle);
  return p.s2 * (t2_position - position);
}

// Undercut by the generating rack (external gears; internal ones are cut by a
// shaper and have no rack undercut), then involute interference: each tip must
// meet the mate inside the mate's involute. Returns the form roll lengths of
// pinion and wheel (m from T1, T2).
std::pair<double, double> check_undercut_and_interference(const GearPairSpec& spec,
                                                          const SignedPair& p,
                                                          GearPairGeometry& result)
{
  const double form1 = form_roll_length(spec.pinion, 0.5 * p.d1, p.alpha_t);
  const double form2 = form_roll_length(spec.wheel, 0.5 * std::abs(p.d2), p.alpha_t);
  for (const bool wheel : {false, true})
  {
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    if (g.internal)
      continue;
    const double z = g.teeth;
    const double x_min =
        (g.dedendum_coefficient - g.root_radius_coefficient * (1. - std::sin(p.alpha_n))) -
        z * std::sin(p.alpha_t) * std::sin(p.alpha_t) / (2. * std::cos(p.beta));
    (wheel ? result.wheel : result.pinion).minimum_profile_shift = x_min;
    if ((wheel ? form2 : form1) < 0.)
      throw InputError(field::gear(wheel, "profile_shift"),
                       "x = " + format_number(g.profile_shift, 4) +
                           " undercuts the tooth (x_min = " + format_number(x_min, 4) +
                           " for z = " + std::to_string(g.teeth) + ")");
  }
  if (result.contact_start < form1)
    throw InputError(field::gear(true, "tip_diameter"),
                     "the wheel tip reaches below the pinion's involute (involute "
                     "interference: contact starts " +
                         millimetres(result.contact_start) +
                         " from T1, the pinion form circle at " + millimetres(form1) + "); " +
                         (spec.wheel.internal
                              ? "set it to auto (the longest ring teeth that clear the pinion's "
                                "involute) or a larger ring tip diameter"
                              : "set it to auto (the standard tip for this pair) or a smaller "
                                "wheel tip diameter"));
  const double wheel_roll_at_end = wheel_roll_length(p, result, result.contact_end);
  if (spec.wheel.internal ? wheel_roll_at_end > form2 : wheel_roll_at_end < form2)
    throw InputError(field::gear(false, "tip_diameter"),
                     "the pinion tip reaches beyond the wheel's involute (involute "
                     "interference at roll length " +
                         millimetres(wheel_roll_at_end) + ", wheel form limit " +
                         millimetres(form2) +
                         "); set it to auto (the standard tip for this "
                         "pair) or a smaller pinion tip diameter");
  return {form1, form2};
}

// Radial tip clearances (internal: the ring's root circle encloses the pinion
// tip).
void check_tip_clearances(const GearPairSpec& spec, const SignedPair& p, GearPairGeometry& result)
{
  const double ra1 = 0.5 * std::abs(p.da1), ra2 = 0.5 * std::abs(p.da2);
  const double rf1 = 0.5 * std::abs(p.df1), rf2 = 0.5 * std::abs(p.df2);
  const bool internal = spec.wheel.internal;
  result.tip_clearance_pinion =
      internal ? rf2 - result.centre_distance - ra1 : result.centre_distance - ra1 - rf2;
  result.tip_clearance_wheel =
      internal ? ra2 - result.centre_distance - rf1 : result.centre_distance - ra2 - rf1;
  if (result.tip_clearance_pinion < 0.)
    throw InputError(field::gear(false, "tip_diameter"),
                     "the pinion tip hits the wheel root (clearance " +
                         millimetres(result.tip_clearance_pinion) + ")");
  if (result.tip_clearance_wheel < 0.)
    throw InputError(field::gear(true, "tip_diameter"),
                     "the wheel tip hits the pinion root (clearance " +
                         millimetres(result.tip_clearance_wheel) + ")");
}

// Tip/tip (trochoid) interference of an internal pair over the whole circle (KHK Gear Technical
// Reference, internal gears, docs/references.md §11): leaving the mesh, the pinion tip runs on a
// trochoid relative to the ring and must pass the ring's tip corner where the two tip circles
// cross. With the crossing at angle θ1 on the pinion and θ2 on the ring (from the centre line),
//   θ1·z1/z2 + inv α_w − inv α_a2 − θ2 ≥ 0,
//   cos θ1 = (r_a2² − r_a1² − a²)/(2·a·r_a1),  θ1 += inv α_a1 − inv α_w,
//   cos θ2 = (a² + r_a2² − r_a1²)/(2·a·r_a2).
// When the pinion's tip circle encloses the ring's (r_a1 − a ≥ r_a2) the teeth overlap all around
// and the pair cannot turn at all: the tooth difference is too small for these tips.
void check_internal_tip_interference(const GearPairSpec& spec, const SignedPair& p,
                                     const GearPairGeometry& result)
{
  if (!spec.wheel.internal)
    return;
  const double ra1 = 0.5 * std::abs(p.da1), ra2 = 0.5 * std::abs(p.da2);
  const double rb1 = 0.5 * std::abs(p.db1), rb2 = 0.5 * std::abs(p.db2);
  const double a = result.centre_distance;
  const int difference = spec.wheel.teeth - spec.pinion.teeth;
  if (ra1 - a >= ra2)
    throw InputError(field::gear(true, "teeth"),
                     "a tooth difference of " + std::to_string(difference) +
                         " is too small for these tips: the pinion's tip circle (d_a1 = " +
                         millimetres(2. * ra1) + " at a = " + millimetres(a) +
                         ") encloses the ring's (d_a2 = " + millimetres(2. * ra2) +
                         "), so the teeth overlap all around and the pair cannot turn");
  const double c1 = (ra2 * ra2 - ra1 * ra1 - a * a) / (2. * a * ra1);
  const double c2 = (a * a + ra2 * ra2 - ra1 * ra1) / (2. * a * ra2);
  if (!(c1 > -1. && c1 < 1. && c2 > -1. && c2 < 1.))
    return; // the tip circles do not cross: no tip meets a tip away from the mesh
  const auto inv = [](double alpha) { return involute(alpha); };
  const double alpha_w = result.working_pressure_angle;
  const double alpha_a1 = std::acos(std::min(1., rb1 / ra1));
  const double alpha_a2 = std::acos(std::min(1., rb2 / ra2));
  const double theta1 = std::acos(c1) + inv(alpha_a1) - inv(alpha_w);
  const double theta2 = std::acos(c2);
  const double margin =
      theta1 * spec.pinion.teeth / spec.wheel.teeth + inv(alpha_w) - inv(alpha_a2) - theta2;
  if (margin < 0.)
    throw InputError(
        field::gear(true, "teeth"),
        "a tooth difference of " + std::to_string(difference) +
            " gives tip interference away from the mesh: the ring's tips cut the "
            "pinion's tips as they leave (trochoid interference, margin " +
            format_number(margin * 180. / pi, 3) +
            "°); use more ring teeth, a shorter ring or pinion tip or a profile shift");
}

// Per-gear diameters and the tip thickness s_at = d_a·(s_t/d + inv α_t − inv
// α_at) (ISO 21771); for an internal gear the tooth narrows towards its (inner)
// tip, which the DIN signs of d and d_a take care of.
void set_gear_geometry(const GearPairSpec& spec, const SignedPair& p,
                       std::pair<double, double> form_rolls, GearPairGeometry& result)
{
  const double cos_wt = std::cos(result.working_pressure_angle);
  for (const bool wheel : {false, true})
  {
    const GearSpec& g = wheel ? spec.wheel : spec.pinion;
    GearGeometry& out = wheel ? result.wheel : result.pinion;
    const double d = wheel ? p.d2 : p.d1;
    const double db = wheel ? p.db2 : p.db1;
    const double da = wheel ? p.da2 : p.da1;
    out.reference_diameter = std::abs(d);
    out.base_diameter = std::abs(db);
    out.tip_diameter = std::abs(da);
    out.tip_form_diameter = wheel ? p.dFa2 : p.dFa1;
    out.root_diameter = std::abs(wheel ? p.df2 : p.df1);
    out.working_diameter = std::abs(db) / cos_wt;
    const double form = wheel ? form_rolls.second : form_rolls.first;
    out.form_diameter = 2. * std::sqrt(0.25 * db * db + form * form);
    const double active_roll =
        wheel ? wheel_roll_length(p, result, result.contact_end) : result.contact_start;
    out.active_profile_start = 2. * std::sqrt(0.25 * db * db + active_roll * active_roll);
    out.tooth_thickness = reference_tooth_thickness(g, p);
    out.tip_pressure_angle = std::acos(db / da);
    out.tip_thickness = normal_tip_thickness(g, p, wheel);
    // A tip thinner than 0.2·m_n is commonly held too fragile (hardened:
    // 0.4·m_n).
    if (out.tip_thickness < 0.2 * p.m_n)
      result.warnings.push_back(std::string(wheel ? "wheel" : "pinion") + " tip thickness " +
                                millimetres(out.tip_thickness) + " is below 0.2·m_n");
  }
}

// Contact zones: the pair count changes where a pair enters (A + k·p_bt) or
// leaves (E − k·p_bt).
void set_contact_zones(GearPairGeometry& result)
{
  std::vector<double> breaks{result.contact_start, result.contact_end};
  for (double p = result.contact_start + result.transverse_base_pitch; p < result.contact_end;
       p += result.transverse_base_pitch)
    breaks.push_back(p);
  for (double p = result.contact_end - result.transverse_base_pitch; p > result.contact_start;
       p -= result.transverse_base_pitch)
    breaks.push_back(p);
  std::sort(breaks.begin(), breaks.end());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
  {
    if (breaks[i + 1] - breaks[i] < 1e-12 * result.transverse_base_pitch)
      continue;
    ContactZone zone;
    zone.start = breaks[i];
    zone.end = breaks[i + 1];
    zone.pairs = result.pairs_in_contact(0.5 * (zone.start + zone.end));
    zone.pinion_roll_start = result.pinion_roll_angle(zone.start);
    zone.pinion_roll_end = result.pinion_roll_angle(zone.end);
    if (!result.contact_zones.empty() && result.contact_zones.back().pairs == zone.pairs)
    {
      result.contact_zones.back().end = zone.end;
      result.contact_zones.back().pinion_roll_end = zone.pinion_roll_end;
    }
    else
      result.contact_zones.push_back(zone);
  }
}
} // namespace

GearPairGeometry compute_gear_pair(const GearPairSpec& spec)
{
  check_pair_spec(spec);
  const SignedPair p = signed_pair(spec);
  GearPairGeometry result;
  result.spec = spec;
  result.transverse_module = p.m_t;
  result.transverse_pressure_angle = p.alpha_t;
  result.base_helix_angle = std::asin(std::sin(p.beta) * std::cos(p.alpha_n));
  result.gear_ratio = spec.wheel.teeth / p.z1;
  set_working_pressure_angle(spec, p, result);
  result.spec.pinion.tip_diameter = std::abs(p.da1);
  result.spec.wheel.tip_diameter = std::abs(p.da2);
  check_tips_and_bores(spec, p);
  check_tip_thickness(spec, p);
  check_tip_rounding(spec, p);
  set_line_of_action(p, result);
  const std::pair<double, double> form_rolls = check_undercut_and_interference(spec, p, result);
  check_rounding_above_form(spec, p, form_rolls);
  check_tip_clearances(spec, p, result);
  check_internal_tip_interference(spec, p, result);
  set_gear_geometry(spec, p, form_rolls, result);

  result.transverse_base_pitch = pi * p.m_t * std::cos(p.alpha_t);
  result.normal_base_pitch = pi * p.m_n * std::cos(p.alpha_n);
  result.path_of_contact = result.contact_end - result.contact_start;
  result.transverse_contact_ratio = result.path_of_contact / result.transverse_base_pitch;
  result.common_face_width = std::min(spec.pinion.face_width, spec.wheel.face_width);
  result.overlap_ratio = result.common_face_width * std::sin(p.beta) / (pi * p.m_n);
  result.total_contact_ratio = result.transverse_contact_ratio + result.overlap_ratio;
  check_contact_ratio(result);
  set_contact_zones(result);
  return result;
}

double clearing_ring_tip_diameter(const GearPairSpec& spec, double margin)
{
  const std::string parameter = field::gear(true, "tip_diameter");
  if (!spec.wheel.internal)
    throw InputError(parameter, "an automatic tip is offered for internal wheels only");
  check_gear(spec.wheel, true);
  // A ring's tip lies inside its reference circle; the longest teeth reach down towards the
  // base circle.
  const double m_n = spec.wheel.normal_module;
  const double reference = spec.wheel.teeth * m_n / std::cos(spec.wheel.helix_angle);
  const double base = reference * std::cos(spec.wheel.pressure_angle);
  check_pair_spec(spec);
  std::optional<InputError> tooth_difference; // the pair's own reason, if no tip can help
  const auto clears = [&](double tip)
  {
    GearPairSpec trial = spec;
    trial.wheel.tip_diameter = tip;
    try
    {
      const GearPairGeometry pair = compute_gear_pair(trial);
      const double rb1 = 0.5 * pair.pinion.base_diameter;
      const double form_roll = std::sqrt(
          std::max(0., 0.25 * pair.pinion.form_diameter * pair.pinion.form_diameter - rb1 * rb1));
      return pair.contact_start - form_roll >= margin;
    }
    catch (const InputError& e)
    {
      // A failure that names another parameter than the ring's tip (a pointed pinion, a bore,
      // the tooth difference) is the pair's own: no tip can mend it.
      if (e.parameter() != parameter && e.parameter() != field::gear(false, "tip_diameter") &&
          !tooth_difference)
        tooth_difference = e;
      return false;
    }
  };
  // Short ring teeth fail on ε_α < 1, long ones on interference: find a valid tip from the
  // reference circle down, then bisect towards the interference limit below it. The teeth are
  // never longer than the standard d − 2·m_n·(h_aP* + x): the generating cutter's dedendum ends
  // there (geometry/involute_tooth.cc refuses a deeper tip as topped), so a longer tip would
  // pass here and fail in every FE scene (found by tests/invariants: a 31/86 ring, x 0.38/0.33,
  // whose interference limit lay 8 µm beyond its standard tip).
  const double longest = std::max(
      base, reference - 2. * m_n * (spec.wheel.addendum_coefficient + spec.wheel.profile_shift));
  const int steps = 400;
  int step = 0;
  const auto at = [&](int i) { return reference - i * (reference - longest) / steps; };
  while (step < steps && !clears(at(step)))
    ++step;
  if (step == steps && tooth_difference)
    throw *tooth_difference;
  if (step == steps)
    throw InputError(parameter, "no ring tip between the base and reference circles clears the "
                                "pinion's involute with a margin of " +
                                    millimetres(margin) + " at ε_α ≥ 1");
  if (clears(longest)) // the standard tip already clears: the longest teeth allowed
    return longest;
  double low = longest, high = at(step);
  while (high - low > 1e-12)
  {
    const double middle = 0.5 * (low + high);
    (clears(middle) ? high : low) = middle;
  }
  return high;
}

GearPairSpec split_path_pair()
{
  constexpr double degree = pi / 180.;
  GearPairSpec spec;
  spec.pinion.teeth = 21;
  spec.wheel.teeth = 57;
  for (GearSpec* gear : {&spec.pinion, &spec.wheel})
  {
    gear->normal_module = 2.5e-3;
    gear->pressure_angle = 20. * degree;
    gear->helix_angle = 0.;
  }
  spec.pinion.profile_shift = 0.29;
  spec.wheel.profile_shift = -0.29;
  spec.pinion.face_width = 26e-3;
  spec.wheel.face_width = 24e-3;
  spec.pinion.bore_diameter = 20e-3;
  spec.wheel.bore_diameter = 40e-3;

  // ε_α falls monotonically as both tip radii shrink by the same Δ: bisect for
  // ε_α = 1.5 between Δ = 0 (standard tips, ε_α ≈ 1.62) and Δ = m_n/4 (ε_α
  // ≈ 1.35).
  const GearPairGeometry standard = compute_gear_pair(spec);
  const double da1 = standard.pinion.tip_diameter;
  const double da2 = standard.wheel.tip_diameter;
  auto contact_ratio = [&](double reduction)
  {
    GearPairSpec trial = spec;
    trial.pinion.tip_diameter = da1 - 2. * reduction;
    trial.wheel.tip_diameter = da2 - 2. * reduction;
    return compute_gear_pair(trial).transverse_contact_ratio;
  };
  double low = 0., high = 0.25 * spec.pinion.normal_module;
  if (!(contact_ratio(low) > 1.5 && contact_ratio(high) < 1.5))
    throw SolverFailure("split-path tip diameters", "ε_α = 1.5 is not bracketed");
  while (high - low > 1e-15)
  {
    const double middle = 0.5 * (low + high);
    (contact_ratio(middle) > 1.5 ? low : high) = middle;
  }
  spec.pinion.tip_diameter = da1 - (low + high);
  spec.wheel.tip_diameter = da2 - (low + high);
  return spec;
}
} // namespace gearstiff::kinematics
