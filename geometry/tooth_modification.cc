#include "geometry/tooth_modification.h"

#include "errors/errors.h"
#include "geometry/fields.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace gearstiff::geometry
{
namespace
{
std::string um(double length)
{
  std::ostringstream text;
  text.precision(4);
  text << length * 1e6 << " µm";
  return text.str();
}

std::string mm(double length)
{
  std::ostringstream text;
  text.precision(5);
  text << length * 1e3 << " mm";
  return text.str();
}

// The parameter word of a modification kind (the amount's name in Gear pair/Pinion).
std::string kind_name(ModificationKind kind)
{
  switch (kind)
  {
  case ModificationKind::tip_relief:
    return "tip relief";
  case ModificationKind::root_relief:
    return "root relief";
  case ModificationKind::profile_crowning:
    return "profile crowning";
  case ModificationKind::profile_slope:
    break;
  case ModificationKind::tip_chipping:
  case ModificationKind::broken_tooth:
  case ModificationKind::spall:
  case ModificationKind::root_crack:
    return fault_name(kind);
  }
  return "profile slope";
}

bool is_relief(ModificationKind kind)
{
  return kind == ModificationKind::tip_relief || kind == ModificationKind::root_relief;
}

// Relief length actually used (m): the given one, or (length < 0, "auto") the long relief from
// the start of single-tooth contact.
double relief_length(const ToothModification& m, const FlankRollRange& range)
{
  if (m.length >= 0.)
    return m.length;
  return m.kind == ModificationKind::tip_relief ? std::abs(range.tip - range.single_tip)
                                                : std::abs(range.single_root - range.form);
}

// Roll distance of the relief zone's reference end: the tip, or the root form circle.
double relief_distance(const ToothModification& m, const FlankRollRange& range, double roll)
{
  return std::abs(roll - (m.kind == ModificationKind::tip_relief ? range.tip : range.form));
}

double relief_depth(const ToothModification& m, double length, double distance)
{
  if (!(length > 0.) || distance >= length || !(m.amount > 0.))
    return 0.;
  const double x = length - distance; // from the relief start
  const double u = x / length;
  switch (m.shape)
  {
  case ReliefShape::linear:
    return m.amount * u;
  case ReliefShape::parabolic:
    return m.amount * u * u;
  case ReliefShape::arc:
    break;
  }
  // Circle tangent to the flank at the start through the amount at the end.
  const double radius = (length * length + m.amount * m.amount) / (2. * m.amount);
  return radius - std::sqrt(radius * radius - x * x);
}

double depth_of(const ToothModification& m, const FlankRollRange& range, double roll)
{
  const double active = std::abs(range.active_tip - range.active_root);
  switch (m.kind)
  {
  case ModificationKind::tip_relief:
  case ModificationKind::root_relief:
    return relief_depth(m, relief_length(m, range), relief_distance(m, range, roll));
  case ModificationKind::profile_crowning:
  {
    const double middle = 0.5 * (range.active_tip + range.active_root);
    const double z = 2. * (roll - middle) / active;
    return m.amount * z * z;
  }
  case ModificationKind::profile_slope:
    break;
  case ModificationKind::tip_chipping: // faults: geometry/tooth_fault.h
  case ModificationKind::broken_tooth:
  case ModificationKind::spall:
  case ModificationKind::root_crack:
    return 0.;
  }
  const double from_root =
      (roll - range.active_root) * (range.active_tip >= range.active_root ? 1. : -1.);
  const double depth =
      m.amount > 0. ? m.amount * from_root / active : -m.amount * (active - from_root) / active;
  return std::max(0., depth);
}

// The roll lengths where a modification has a kink or starts (a point of its own there).
std::vector<double> breakpoints(const std::vector<ToothModification>& modifications,
                                const FlankRollRange& range)
{
  std::vector<double> rolls;
  for (const auto& m : modifications)
    if (is_relief(m.kind) && m.amount > 0.)
    {
      const double length = relief_length(m, range);
      const double end = m.kind == ModificationKind::tip_relief ? range.tip : range.form;
      const double inward = m.kind == ModificationKind::tip_relief
                                ? (range.form > range.tip ? 1. : -1.)
                                : (range.tip > range.form ? 1. : -1.);
      rolls.push_back(end + inward * length);
    }
  return rolls;
}

double roll_of(const Eigen::Vector2d& p, double base_radius)
{
  return std::sqrt(std::max(0., p.squaredNorm() - base_radius * base_radius));
}

bool is_involute(ProfileSegment segment)
{
  return segment == ProfileSegment::root_relief || segment == ProfileSegment::flank ||
         segment == ProfileSegment::relief;
}

// The involute point between two points a, b of one flank at roll length `roll`: the polar
// angle of an involute point is affine in inv(α_r), the normal's angle affine in ρ, so both
// interpolate exactly.
ProfilePoint involute_between(const ProfilePoint& a, const ProfilePoint& b, double roll,
                              double base_radius)
{
  const auto inv = [base_radius](double r)
  {
    const double alpha = std::acos(std::min(1., base_radius / r));
    return std::tan(alpha) - alpha;
  };
  const double ra = a.position.norm(), rb = b.position.norm();
  const double r = std::sqrt(base_radius * base_radius + roll * roll);
  const double w = (inv(r) - inv(ra)) / (inv(rb) - inv(ra));
  const double phi_a = std::atan2(a.position.y(), a.position.x());
  const double phi_b = std::atan2(b.position.y(), b.position.x());
  const double phi = phi_a + w * (phi_b - phi_a);
  const double rho_a = roll_of(a.position, base_radius), rho_b = roll_of(b.position, base_radius);
  const double v = (roll - rho_a) / (rho_b - rho_a);
  const double na = std::atan2(a.normal.y(), a.normal.x());
  const double nb = std::atan2(b.normal.y(), b.normal.x());
  double turn = nb - na;
  turn -= 2. * M_PI * std::round(turn / (2. * M_PI));
  const double n = na + v * turn;
  ProfilePoint p = a;
  p.position = r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  p.normal = Eigen::Vector2d(std::cos(n), std::sin(n));
  p.arc_length = a.arc_length + v * (b.arc_length - a.arc_length);
  return p;
}

// The side of a point for the modification: its own, or for a tip corner the half it lies in.
int point_side(const ProfilePoint& p)
{
  if (p.side != 0)
    return p.side;
  return p.position.y() < 0. ? -1 : 1;
}
} // namespace

bool GearModifications::empty() const
{
  if (!all_teeth.empty() || !lead.empty())
    return false;
  for (const auto& [index, list] : by_tooth)
    if (!list.empty())
      return false;
  return true;
}

double removed_depth(const std::vector<ToothModification>& modifications,
                     const FlankRollRange& range, double roll, bool loaded)
{
  double depth = 0.;
  for (const auto& m : modifications)
    if (loaded || m.flanks == ModifiedFlanks::both)
      depth += depth_of(m, range, roll);
  return depth;
}

FlankTouch touching_point(const PairFlanks& flanks, double at)
{
  const double rho_1 = at, rho_2 = std::abs(at - flanks.t2);
  const auto gap_at = [&](double x, bool& on_flanks)
  {
    const double roll_1 = at + x * flanks.pinion_base_radius / rho_1;
    const double roll_2 = std::abs(at + x * flanks.wheel_base_radius / rho_2 - flanks.t2);
    const auto covers = [](const FlankRollRange& range, double roll)
    { return roll >= std::min(range.form, range.tip) && roll <= std::max(range.form, range.tip); };
    on_flanks = covers(flanks.pinion_range, roll_1) && covers(flanks.wheel_range, roll_2);
    return flanks.pinion_removal(roll_1) + flanks.wheel_removal(roll_2);
  };
  bool on_flanks = true;
  const double at_point = gap_at(0., on_flanks);
  if (!(rho_1 > 0.) || !(rho_2 > 0.))
    return {at_point, 0.};
  const double relative_radius = 1. / (1. / rho_1 + (flanks.internal ? -1. : 1.) / rho_2);
  // Removal only ever removes material (≥ 0), so g(x) − g(0) ≥ x²/(2R) − S(0): the smallest gap
  // lies within |x| ≤ √(2R·S(0)). Sampled coarse, then four times 32× finer about the best
  // sample (last step reach/2²⁶, ~5 pm): the gap is continuous (a relief's start is a kink, not
  // a step), so the smallest sample is within slope × step of the minimum, ~1e-14 m.
  if (!(at_point > 0.) || !(relative_radius > 0.))
    return {at_point, 0.};
  double reach = std::sqrt(2. * relative_radius * at_point);
  double best = at_point, best_x = 0.;
  constexpr int samples = 64;
  for (int level = 0; level < 5; ++level)
  {
    const double centre = best_x, step = reach / samples;
    for (int i = -samples; i <= samples; ++i)
    {
      const double x = centre + i * step;
      const double gap = x * x / (2. * relative_radius) + gap_at(x, on_flanks);
      if (on_flanks && gap < best)
      {
        best = gap;
        best_x = x;
      }
    }
    reach = 2. * step;
  }
  return {best, best_x};
}

void check_modifications(const std::vector<ToothModification>& modifications,
                         const ToothProfile& nominal, const FlankRollRange& range,
                         const std::string& parameter)
{
  const double active = std::abs(range.active_tip - range.active_root);
  double tip_removal = 0., largest_removal = 0.;
  std::string largest; // the modification that removes most at the tip
  for (const auto& m : modifications)
  {
    if (is_fault(m.kind)) // checked by check_faults (geometry/tooth_fault.h)
      continue;
    const std::string name = field::gear_entry(parameter, kind_name(m.kind));
    if (m.kind != ModificationKind::profile_slope && !(m.amount >= 0.))
      throw InputError(name, "must be 0 or positive (material removed, µm)");
    if (!std::isfinite(m.amount))
      throw InputError(name, "must be a finite amount (µm)");
    if (is_relief(m.kind))
    {
      const double length = relief_length(m, range);
      if (m.amount > 0. && !(length > 0.))
        throw InputError(name + "_length", "must be positive (mm) or auto");
      if (length > active * (1. + 1e-9))
        throw InputError(name + "_length", mm(length) + " is longer than the active profile (" +
                                               mm(active) + " along the path of contact)");
    }
    const double removal = (m.flanks == ModifiedFlanks::both ? 2. : 1.) *
                           std::max(depth_of(m, range, range.tip), depth_of(m, range, range.form));
    tip_removal += removal;
    if (removal > largest_removal)
    {
      largest_removal = removal;
      largest = name;
    }
    if (2. * std::abs(m.amount) >= nominal.tip_thickness)
      throw InputError(name, um(m.amount) + " reaches the tooth thickness (tip " +
                                 um(nominal.tip_thickness) + ")");
  }
  if (tip_removal >= nominal.tip_thickness)
    throw InputError(field::gear_entry(parameter, kind_name(modifications.front().kind)),
                     "the modifications together remove " + um(tip_removal) +
                         " across the tooth, beyond its tip thickness " +
                         um(nominal.tip_thickness));
  // The relieved tip keeps a land of 0.05·m_n: 2 × 800 µm on the built-in pinion (m_n 2.5 mm,
  // tip 1716 µm) left 116 µm, which gmsh could not mesh (the pinion got no cells and deal.II's
  // reader failed on a scratch file); 2 × 790 µm (136 µm) meshed.
  const double module = nominal.teeth > 0 ? 2. * nominal.reference_radius / nominal.teeth : 0.;
  const double land = 0.05 * module;
  if (largest_removal > 0. && nominal.tip_thickness - tip_removal < land)
    throw InputError(
        largest, "the modifications remove " + um(tip_removal) + " across the tooth and leave " +
                     um(nominal.tip_thickness - tip_removal) + " of its tip " +
                     um(nominal.tip_thickness) + ", under the land of 0.05·m_n = " + um(land) +
                     " the tooth keeps: remove at most " + um(nominal.tip_thickness - land) +
                     " across the tooth (" + um(0.5 * (nominal.tip_thickness - land)) +
                     " on each flank)");
}

namespace
{
// Step 1 of modified_tooth: the nominal points with a point of its own at every kink of the
// flanks (roll lengths `kinks` [m]).
std::vector<ProfilePoint> points_with_kinks(const ToothProfile& nominal,
                                            const std::vector<double>& kinks)
{
  const double rb = nominal.base_radius;
  std::vector<ProfilePoint> points;
  points.reserve(nominal.points.size() + 2 * kinks.size());
  for (std::size_t i = 0; i < nominal.points.size(); ++i)
  {
    points.push_back(nominal.points[i]);
    if (i + 1 == nominal.points.size())
      break;
    const ProfilePoint& a = nominal.points[i];
    const ProfilePoint& b = nominal.points[i + 1];
    if (!(is_involute(a.segment) && is_involute(b.segment) && a.side == b.side && a.side != 0))
      continue;
    const double rho_a = roll_of(a.position, rb), rho_b = roll_of(b.position, rb);
    std::vector<double> inside;
    for (const double k : kinks)
      if ((k - rho_a) * (k - rho_b) < 0. && std::abs(k - rho_a) > 1e-9 &&
          std::abs(k - rho_b) > 1e-9)
        inside.push_back(k);
    std::sort(inside.begin(), inside.end(),
              [&](double x, double y) { return std::abs(x - rho_a) < std::abs(y - rho_a); });
    for (const double k : inside)
      points.push_back(involute_between(a, b, k, rb));
  }
  return points;
}
// A point of a tip rounding's arc, or the arc's end on the tip circle.
bool is_rounding(const std::vector<ProfilePoint>& points, std::size_t i)
{
  const ProfileSegment s = points[i].segment;
  if (s == ProfileSegment::tip_round)
    return true;
  return s == ProfileSegment::tip &&
         ((i > 0 && points[i - 1].segment == ProfileSegment::tip_round) ||
          (i + 1 < points.size() && points[i + 1].segment == ProfileSegment::tip_round));
}

// The translation of a tip rounding's arc: the depth removed where it meets the flank, along
// that point's normal.
struct RoundingMove
{
  Eigen::Vector2d normal = Eigen::Vector2d::Zero(); // unit, the flank's at d_Fa
  double depth = 0.;                                // m
};

// Per side (−1: [0], +1: [1]) the translation of a tip rounding (none: depth 0); its junction
// with the flank is the arc's point next to an involute point.
std::vector<RoundingMove>
rounding_translations(const std::vector<ProfilePoint>& points,
                      const std::function<double(const ProfilePoint&, bool)>& depth,
                      int loaded_side)
{
  std::vector<RoundingMove> moves(2);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const ProfilePoint& p = points[i];
    if (p.segment != ProfileSegment::tip_round)
      continue;
    const bool next_involute = i + 1 < points.size() && is_involute(points[i + 1].segment);
    const bool previous_involute = i > 0 && is_involute(points[i - 1].segment);
    if (!next_involute && !previous_involute)
      continue;
    RoundingMove& move = moves[point_side(p) < 0 ? 0 : 1];
    move.normal = p.normal;
    move.depth = depth(p, point_side(p) == loaded_side);
  }
  return moves;
}

// How a fillet carries its flank's removal (step 3 of modified_tooth). The profile modifications
// remove material from the involute only, and most of them remove some at the form circle: root
// relief its whole amount, profile crowning the parabola's value beyond the active profile, a
// negative slope its amount and more. Left there, the flank's first point sits δ_f inside the
// fillet's last one: a step the outline's spline turns into a notch, and the root stress read on
// the fillet became that notch's, growing as the mesh refined there (case 15 of the invariants'
// seed 20261201, a ring with 2.7 µm profile crowning and a −2.8 µm slope: 124 MPa on the rolling
// mesh, 85 on a mesh per position). The fillet takes the removal instead, as the lead
// modifications' blend does (geometry/tooth_modification_lead.h): δ_f·(3u² − 2u³) over the
// fillet's arc length u ∈ [0, 1] from its root end (0, where the neighbouring outline goes on
// unmoved) to the form point (1) — continuous, flat at both ends, never deeper than δ_f. The
// outline keeps a kink at the form point of the flank's own slope dδ/ds there (the removal per
// arc length of the modified involute, what the flank turns by anyway); meeting that slope too
// was tried and dropped: near the base circle ds = (ρ/r_b)·dρ makes it steep (a 15 µm root
// relief over 0.5 mm of roll on the built-in pinion: −0.6), and a cubic that follows it bulges
// the fillet by several δ_f. A ground flank that runs out into its fillet without a grinding
// notch; what a real fillet is after grinding depends on the tool (protuberance), which the
// profile's data do not say.
struct FilletBlend
{
  bool active = false;
  double depth_at_form = 0.;                              // m, δ_f
  double root_arc = 0.;                                   // m, arc length of the fillet's root end
  double length = 0.;                                     // m, the fillet's arc length
  Eigen::Vector2d towards_form = Eigen::Vector2d::Zero(); // chord from the root end to the form
};

std::vector<FilletBlend> fillet_blends(const std::vector<ProfilePoint>& points,
                                       const std::vector<ToothModification>& modifications,
                                       const FlankRollRange& range, int loaded_side,
                                       double base_radius)
{
  std::vector<FilletBlend> blends(2);
  for (std::size_t f = 0; f < points.size(); ++f)
  {
    if (!is_involute(points[f].segment) || points[f].side == 0)
      continue;
    const int side = points[f].side;
    const auto fillet_of_side = [&](std::size_t i)
    { return points[i].segment == ProfileSegment::fillet && points[i].side == side; };
    // The form point: an involute point next to a fillet point of its side; the fillet runs
    // away from it to its root end.
    int step = 0;
    if (f > 0 && fillet_of_side(f - 1))
      step = -1;
    else if (f + 1 < points.size() && fillet_of_side(f + 1))
      step = 1;
    if (step == 0)
      continue;
    std::size_t r = f;
    while (true)
    {
      const std::ptrdiff_t next = static_cast<std::ptrdiff_t>(r) + step;
      if (next < 0 || next >= static_cast<std::ptrdiff_t>(points.size()) ||
          !fillet_of_side(static_cast<std::size_t>(next)))
        break;
      r = static_cast<std::size_t>(next);
    }
    FilletBlend& blend = blends[side < 0 ? 0 : 1];
    blend.depth_at_form = removed_depth(
        modifications, range, roll_of(points[f].position, base_radius), side == loaded_side);
    blend.root_arc = points[r].arc_length;
    blend.length = std::abs(points[f].arc_length - points[r].arc_length);
    blend.towards_form = points[f].position - points[r].position;
    blend.active = blend.length > 0. && blend.depth_at_form > 0.;
  }
  return blends;
}

// Moves a fillet point by its blend (step 3 of modified_tooth); its normal turns by dδ/ds.
void blend_fillet_point(ProfilePoint& p, const FilletBlend& blend)
{
  const double u = std::min(1., std::abs(p.arc_length - blend.root_arc) / blend.length);
  const double d = blend.depth_at_form;
  const double depth = d * u * u * (3. - 2. * u);
  const double slope = d * 6. * u * (1. - u) / blend.length;
  Eigen::Vector2d tangent(-p.normal.y(), p.normal.x());
  if (tangent.dot(blend.towards_form) < 0.)
    tangent = -tangent;
  p.position -= depth * p.normal;
  p.normal = (p.normal + slope * tangent).normalized();
}
} // namespace

ToothProfile modified_tooth(const ToothProfile& nominal,
                            const std::vector<ToothModification>& modifications,
                            const FlankRollRange& range, int loaded_side,
                            const std::string& parameter)
{
  if (modifications.empty())
    return nominal;
  check_modifications(modifications, nominal, range, parameter);
  const double rb = nominal.base_radius;
  const std::vector<double> kinks = breakpoints(modifications, range);

  // 1. The nominal points with a point of its own at every kink of the flanks.
  std::vector<ProfilePoint> points = points_with_kinks(nominal, kinks);

  // 2. Every flank point (and the tip corners) moves inwards by δ(ρ), its normal turns by dδ/ds;
  //    points inside a relief zone are marked, so the relief starts a new outline piece. A tip
  //    rounding's arc (and its end on the tip circle) moves with the flank point it meets, along
  //    that point's normal, like a sharp tip corner.
  const std::vector<RoundingMove> rounding_moves = rounding_translations(
      points,
      [&](const ProfilePoint& p, bool loaded)
      { return removed_depth(modifications, range, roll_of(p.position, rb), loaded); },
      loaded_side);
  // 3. The fillets take their flank's removal at the form circle (FilletBlend), from the nominal
  //    points, before step 2 moves the form points.
  const std::vector<FilletBlend> blends =
      fillet_blends(points, modifications, range, loaded_side, rb);
  ToothProfile tooth = nominal;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    ProfilePoint& p = points[i];
    if (p.segment == ProfileSegment::fillet && p.side != 0)
    {
      const FilletBlend& blend = blends[p.side < 0 ? 0 : 1];
      if (blend.active)
        blend_fillet_point(p, blend);
      continue;
    }
    if (is_rounding(points, i))
    {
      const RoundingMove& move = rounding_moves[point_side(p) < 0 ? 0 : 1];
      p.position -= move.depth * move.normal;
      continue;
    }
    const bool corner = p.segment == ProfileSegment::tip &&
                        ((i > 0 && is_involute(points[i - 1].segment)) ||
                         (i + 1 < points.size() && is_involute(points[i + 1].segment)));
    if (!is_involute(p.segment) && !corner)
      continue;
    const bool loaded = point_side(p) == loaded_side;
    const double rho = roll_of(p.position, rb);
    const double depth = removed_depth(modifications, range, rho, loaded);
    if (depth == 0.)
      continue;
    // dδ/ds on the involute: ds = (ρ/r_b)·dρ; the tangent of increasing ρ points outwards.
    const double h = 1e-7;
    const double slope = (removed_depth(modifications, range, rho + h, loaded) -
                          removed_depth(modifications, range, std::max(0., rho - h), loaded)) /
                         (rho + h - std::max(0., rho - h));
    if (corner)
    {
      // The tip corner moves with its flank (along the flank's normal, not the tip circle's);
      // it stays a tip point with the tip circle's normal.
      const std::size_t flank = (i > 0 && is_involute(points[i - 1].segment)) ? i - 1 : i + 1;
      p.position -= depth * points[flank].normal;
      continue;
    }
    const Eigen::Vector2d nominal_normal = p.normal;
    Eigen::Vector2d tangent(-p.normal.y(), p.normal.x());
    if (tangent.dot(p.position) < 0.)
      tangent = -tangent;
    p.position -= depth * nominal_normal;
    if (rho > 0.)
      p.normal = (nominal_normal + slope * rb / rho * tangent).normalized();
    for (const auto& m : modifications)
    {
      if (!is_relief(m.kind) || !(m.amount > 0.) || !(loaded || m.flanks == ModifiedFlanks::both))
        continue;
      const double distance = relief_distance(m, range, rho);
      const double length = relief_length(m, range);
      if (m.kind == ModificationKind::tip_relief && distance <= length * (1. + 1e-12) + 1e-12)
        p.segment = ProfileSegment::relief;
      else if (m.kind == ModificationKind::root_relief && distance < length - 1e-12 &&
               p.segment == ProfileSegment::flank)
        p.segment = ProfileSegment::root_relief;
    }
  }
  tooth.points = points;
  return tooth;
}

bool is_fault(ModificationKind kind)
{
  return kind == ModificationKind::tip_chipping || kind == ModificationKind::broken_tooth ||
         kind == ModificationKind::spall || kind == ModificationKind::root_crack;
}

bool has_faults(const std::vector<ToothModification>& modifications)
{
  return std::any_of(modifications.begin(), modifications.end(),
                     [](const ToothModification& m) { return is_fault(m.kind); });
}

std::string fault_name(ModificationKind kind)
{
  switch (kind)
  {
  case ModificationKind::tip_chipping:
    return "tip chipping";
  case ModificationKind::broken_tooth:
    return "broken tooth";
  case ModificationKind::spall:
    return "spall depth";
  default:
    break;
  }
  return "crack depth";
}

ReliefShape parse_relief_shape(const std::string& text, const std::string& parameter)
{
  if (text == "linear")
    return ReliefShape::linear;
  if (text == "parabolic")
    return ReliefShape::parabolic;
  if (text == "arc")
    return ReliefShape::arc;
  throw InputError(parameter, "'" + text + "' is not one of linear, parabolic, arc");
}

ModifiedFlanks parse_modified_flanks(const std::string& text, const std::string& parameter)
{
  if (text == "loaded")
    return ModifiedFlanks::loaded;
  if (text == "both")
    return ModifiedFlanks::both;
  throw InputError(parameter, "'" + text + "' is not one of loaded, both");
}
} // namespace gearstiff::geometry
