// The influence-coefficient model's geometry along the face and the line of action
// (docs/ltca.md §3): the node planes that carry its unknowns, a helical pair's contact lines,
// the part of a line on the path, the tip corners beyond it and the designed separation of the
// modified flanks. Internal to stiffness/ (stiffness/influence_sweep.cc).
#pragma once

#include "geometry/tooth_modification.h"
#include "geometry/tooth_modification_lead.h"
#include "kinematics/gear_pair.h"
#include "stiffness/influence_body.h"
#include "stiffness/mesh_stiffness.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace gearstiff::stiffness::influence
{
// Where along the face the model has its unknowns (docs/ltca.md §3): in 2D one station, the
// whole face b; in 3D the FE body's node planes z_i = i·Δz (i = 0 … layers), each carrying the
// line load of its tributary width (Δz, Δz/2 at the faces). These are the planes on which the
// exact path reports its nodal line loads (stiffness/face_load.h), so K_Hβ is the same statistic
// in both; the layers' middles (the first 3D model's stations) made it +2 % (docs/ltca.md §3).
struct FaceStations
{
  std::vector<double> z;     // m
  std::vector<double> width; // m, Σ = b
  double layer = 0.;         // m, Δz (3D)
  std::size_t size() const { return z.size(); }
};
FaceStations face_stations(int dim, unsigned int layers, double face_width);

// A helical pair's contact lines (docs/ltca.md §3 "Helical"; geometry/gear_pair_helix.cc): the
// section at z of the twisted scene is the transverse model (its middle z₀ = b/2) turned about
// each gear's axis by the lead, so pair j touches section z at ℓ_j(z) = ℓ_j + rate·(z − z₀),
// rate = ±tan β_b by the pinion's hand (geometry::detail::contact_shift_rate and model_section,
// repeated here: internal to geometry/), and the flank normal leaves the transverse plane by β_b.
// A spur pair: rate 0, cos β_b = 1, every formula the spur model's, digit for digit.
struct Helix
{
  double rate = 0.;     // -, dℓ/dz
  double middle = 0.;   // m, z₀
  double cos_base = 1.; // -, cos β_b
  explicit Helix(const kinematics::GearPairGeometry& pair)
  {
    if (pair.spec.pinion.helix_angle == 0.)
      return;
    rate = (pair.spec.pinion.helix_angle > 0. ? 1. : -1.) * std::tan(pair.base_helix_angle);
    middle = 0.5 * pair.common_face_width;
    cos_base = std::cos(pair.base_helix_angle);
  }
  double shift(double z) const { return rate == 0. ? 0. : rate * (z - middle); } // m
  // rad/m, dφ/dz of one gear's sections (counter-clockwise): its roll rate/r_b, the wheel turning
  // the other way on an external pair (geometry::detail::gear_twists).
  double turn_rate(const PairFrame& frame, bool wheel) const
  {
    return wheel ? (frame.pair.spec.wheel.internal ? 1. : -1.) * rate / frame.wheel_base_radius()
                 : rate / frame.pinion_base_radius();
  }
};

// The part of station s's tributary width (m) where a helical contact line through ℓ = `at` at
// the station's plane lies on the path A–E (ℓ(z) = at + rate·(z − z_s)): the line leaves the
// flanks at A (the wheel's tip) and E (the pinion's), so a station whose strip the line leaves
// carries its load only over this length (docs/ltca.md §3 "Line ends"). Spur: the whole width.
double on_path_width(const FaceStations& stations, const Helix& helix,
                     const kinematics::GearPairGeometry& pair, std::size_t s, double at);

// The kinematic gap (m, transverse, along the line of action) of a tip corner in a section whose
// contact line lies beyond the path by the roll `beyond` (m, > 0): at E the pinion's tip corner
// against the wheel's flank, at A (`at_start`) the wheel's tip corner against the pinion's. The
// corner is the path's end point turned with its gear by the roll beyond it; every point lies on
// one involute of the mate's base circle, and two involutes of one base circle are the distance
// between their contact points on the line of action apart along their common normal, so the gap
// is |ℓ(corner's involute) − ℓ(the mate flank's)|. External and internal pairs. A rounded tip
// (`rounding`, m, the tip's rounding radius: the pinion's at E, the wheel's at A): the arc's gap,
// its centre's less the radius.
double tip_corner_gap(const PairFrame& frame, double beyond, bool at_start, double rounding = 0.);

// m, the depth by which a rounded tip's arc lies under the involute's continuation beyond the tip
// form circle, at the flank point of roll `roll` (ρ = √(r² − r_b²); 0 up to the form roll
// `form_roll`), measured along that point's inward normal as the profile modifications are
// (geometry/tooth_modification.h): the arc of radius `radius` is tangent to the involute at the
// form roll. An external gear's flank is convex, its tip at larger rolls; a ring's (`internal`)
// is concave, its tip at smaller rolls, the arc's centre on the far side of the flank
// (kinematics::tip_form_diameter, σ = −1). Where the normal misses the arc (far beyond the tip)
// the depth to its nearest approach. Closed form near the form roll: with x the arc length along
// the flank beyond it, x²/2·(1/r ∓ 1/ρ_F) (− external, + internal).
double rounded_tip_removal(double base_radius, double form_roll, double radius, double roll,
                           bool internal = false);

// m, one loaded flank's removal at its roll: its profile modifications' and, with a rounded tip
// (`rounding` > 0), the arc's beyond the tip form circle.
inline double flank_removal(const std::vector<geometry::ToothModification>& list,
                            const geometry::FlankRollRange& range, double base_radius,
                            double rounding, double roll, bool internal = false)
{
  return geometry::removed_depth(list, range, roll, true) +
         rounded_tip_removal(base_radius, range.tip, rounding, roll, internal);
}

// The designed separation of a pair at ℓ: both loaded flanks' removal at their roll lengths
// (the same on every tooth: faults are refused), as geometry::unloaded_transmission_errors. A
// rounded tip adds its arc beyond the tip form circle (rounded_tip_removal: the near field's gap
// then carries a contact onto the arc, docs/ltca.md "Tip rounding").
class PairSeparation
{
public:
  PairSeparation(const GearMeshStiffnessSettings& settings, const PairFrame& frame);
  double operator()(double at) const { return removal(at, false) + removal(at, true); }
  // Where the modified flanks first touch near ℓ: the smallest gap over the tangential offset
  // (geometry::touching_separation, as geometry::unloaded_transmission_errors takes it), at most
  // operator()(at).
  geometry::FlankTouch touching(double at) const { return geometry::touching_point(flanks, at); }
  // Any modification that removes material (amount 0 is none: the same coefficients, digit for
  // digit).
  bool modified() const
  {
    if (pinion_rounding > 0. || wheel_rounding > 0.)
      return true;
    for (const auto* list : {&pinion, &wheel})
      for (const geometry::ToothModification& m : *list)
        if (m.amount != 0.)
          return true;
    return false;
  }
  // The depth removed from one gear's loaded flank where it touches at ℓ.
  double removal(double at, bool of_wheel) const
  {
    return of_wheel ? flank_removal(wheel, wheel_range, wheel_base, wheel_rounding,
                                    std::abs(at - t2), flanks.internal)
                    : flank_removal(pinion, pinion_range, pinion_base, pinion_rounding, at);
  }
  // m, the arc length along one gear's loaded flank from its point at ℓ to its tip corner (the
  // involute's ρ²/(2r_b) between their rolls), positive where ℓ grows (the near field's x). A
  // rounded tip's corner is the sharp one its arc replaces (the involute's continuation to the
  // tip circle): the tooth is that wedge at distances beyond the radius; a point on the arc is
  // taken at the tip form circle's distance.
  double tip_corner_offset(double at, bool of_wheel) const
  {
    const double roll = of_wheel ? std::abs(at - t2) : at;
    const double apex = of_wheel ? wheel_apex : pinion_apex;
    const double form = of_wheel ? wheel_range.tip : pinion_range.tip;
    const double base = of_wheel ? wheel_base : pinion_base;
    // Towards the tip: larger rolls on an external gear, smaller on a ring.
    const double towards = of_wheel && flanks.internal ? -1. : 1.;
    const double on_flank = towards * (roll - form) > 0. ? form : roll;
    const double length = std::abs(apex * apex - on_flank * on_flank) / (2. * base);
    // The direction of growing ℓ along this flank: the pinion's roll grows with ℓ, the wheel's
    // falls where ℓ < T1T2.
    const double sense = of_wheel ? (at < t2 ? -1. : 1.) : 1.;
    return towards * sense * length;
  }
  // rad, the transverse pressure angle of one gear's involute at its tip circle: the angle of
  // its tip corner (tip_corner_offset's, the sharp one a rounded tip replaces).
  double tip_pressure_angle(bool of_wheel) const
  {
    return of_wheel ? std::atan(wheel_apex / wheel_base) : std::atan(pinion_apex / pinion_base);
  }
  // The depth removed from one gear's loaded flank at z (m) of the face by its lead
  // modifications (3D; geometry/tooth_modification_lead.h), and from both.
  double lead_removal(double z, bool of_wheel) const
  {
    return geometry::lead_removed_depth(of_wheel ? wheel_lead : pinion_lead, z, face_width, true);
  }
  double lead(double z) const { return lead_removal(z, false) + lead_removal(z, true); }
  // The shortest relief length of either gear (m; infinity without reliefs): a kink of the gap.
  double shortest_relief() const
  {
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& [list, range] :
         {std::pair(&pinion, &pinion_range), std::pair(&wheel, &wheel_range)})
      for (const geometry::ToothModification& m : *list)
        if (m.kind == geometry::ModificationKind::tip_relief ||
            m.kind == geometry::ModificationKind::root_relief)
          shortest = std::min(shortest, m.length >= 0. ? m.length
                                        : m.kind == geometry::ModificationKind::tip_relief
                                            ? std::abs(range->tip - range->single_tip)
                                            : std::abs(range->single_root - range->form));
    return shortest;
  }

private:
  std::vector<geometry::ToothModification> pinion, wheel;
  geometry::LeadModification pinion_lead, wheel_lead;
  geometry::FlankRollRange pinion_range, wheel_range;
  double face_width; // m, b
  double t2;
  double pinion_base, wheel_base;                   // m, r_b
  double pinion_rounding = 0., wheel_rounding = 0.; // m, tip rounding radius (0: sharp)
  double pinion_apex = 0., wheel_apex = 0.;         // m, ρ at the tip circle (the sharp corner)
  geometry::PairFlanks flanks; // touching(): the removals above and the pair's radii
};
} // namespace gearstiff::stiffness::influence
