// The gear-pair scene's contact prediction: each pair's contact point with its Hertz estimate and
// gap, the band of foci a rolling sweep needs, the designed separations (unloaded TE).
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/gear_pair_internal.h"
#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_fault.h"
#include "geometry/tooth_modification_lead.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>

namespace gearstiff::geometry
{
using namespace detail;

namespace
{
bool is_loaded_flank(const ProfileEdge& edge, const ToothProfile& tooth)
{
  return is_flank(edge.segment) && edge.side == loaded_side(tooth);
}

// Parameter t of the intersection of origin + t·direction with the loaded flank
// polyline of the given tooth, nearest to t = 0; none if the line misses the flank. The
// polyline is the one meshed: its top piece runs from the tip corner (edge_between).
std::optional<double> flank_intersection(const ToothProfile& tooth, const Eigen::Vector2d& centre,
                                         double rotation, const Eigen::Vector2d& origin,
                                         const Eigen::Vector2d& direction)
{
  std::optional<double> best;
  for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
  {
    if (!is_loaded_flank(edge_between(tooth.points[i], tooth.points[i + 1]), tooth))
      continue;
    const Eigen::Vector2d a = place(tooth.points[i].position, centre, rotation);
    const Eigen::Vector2d b = place(tooth.points[i + 1].position, centre, rotation);
    // Solve origin + t·direction = a + s·(b − a).
    Eigen::Matrix2d m;
    m << direction, a - b;
    if (std::abs(m.determinant()) > 1e-300)
    {
      const Eigen::Vector2d ts = m.inverse() * (a - origin);
      if (ts(1) >= -1e-12 && ts(1) <= 1. + 1e-12 && (!best || std::abs(ts(0)) < std::abs(*best)))
        best = ts(0);
    }
  }
  return best;
}

} // namespace

namespace detail
{
// Predicted contact of pair j with its Hertz estimate and its initial gap measured between the
// placed flank outlines along the line of action.
SceneContact predicted_contact(const GearPairSceneSpec& spec,
                               const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                               const PlacedGears& gears, double reference, int j,
                               double normal_force, double roll)
{
  SceneContact contact;
  // A helical pair may touch only in other sections than the model's: there the gears are the
  // model rolled by `roll` along the line of action (geometry/gear_pair_helix.cc).
  const double position = reference + roll + j * pair.transverse_base_pitch;
  const double pinion_turn = roll / (0.5 * pair.pinion.base_diameter);
  const double wheel_turn =
      (gears.wheel.internal ? 1. : -1.) * roll / (0.5 * std::abs(pair.wheel.base_diameter));
  contact.point = line.at(position);
  contact.normal = line.u;
  // The flank curvature radii are the distances to the tangent points T1 and T2; a ring's
  // flank is concave (negative radius).
  contact.first_curvature_radius = position;
  contact.second_curvature_radius =
      gears.wheel.internal ? -(position - line.t2) : line.t2 - position;
  contact.normal_force = normal_force;
  contact.first_feature = j;
  contact.second_feature = -j;
  if (!(contact.first_curvature_radius > 0. && std::abs(contact.second_curvature_radius) > 0. &&
        (gears.wheel.internal || contact.second_curvature_radius > 0.)))
    throw SolverFailure("gear scene placement", "contact outside the line of action");
  const double face_width = pair.common_face_width;
  contact.hertz_half_width = hertz_half_width(
      normal_force / face_width, contact.first_curvature_radius, contact.second_curvature_radius,
      spec.young_modulus, spec.poisson_ratio, spec.young_modulus, spec.poisson_ratio);
  const auto on_pinion = flank_intersection(
      gears.pinion_contact_teeth.tooth(j), gears.pinion_centre,
      gears.pinion_rotation + pinion_turn + j * gears.pinion.angular_pitch, contact.point, line.u);
  const auto on_wheel = flank_intersection(
      gears.wheel_contact_teeth.tooth(mate_tooth(gears.wheel, j)), gears.wheel_centre,
      gears.wheel_rotation + wheel_turn + mate_tooth(gears.wheel, j) * gears.wheel.angular_pitch,
      contact.point, line.u);
  if (!on_pinion || !on_wheel)
    throw SolverFailure("gear scene placement",
                        "the line of action misses a flank of pair " + std::to_string(j));
  contact.gap = *on_wheel - *on_pinion;
  if (roll != 0.) // the point on the pinion's flank in the model section
    contact.point = place(contact.point - gears.pinion_centre, gears.pinion_centre, -pinion_turn);
  return contact;
}

// Rolling sweeps: refinement along every contact point a flank sees over the swept positions.
// At ℓ the pinion has turned by (ℓ − ℓ_ref)/r_b1 from the scene's placement and the wheel by
// ∓(ℓ − ℓ_ref)/r_b2 (external: the other way; ring: the same way), so pair j's contact point
// line(ℓ + j·p_bt) maps back to the pinion's placement turned by −(ℓ − ℓ_ref)/r_b1 about its
// centre and to the wheel's by ±(ℓ − ℓ_ref)/r_b2 about its own. The roll path is sampled at
// half the fine radius: the discs of the foci then cover a band along the flank.
void add_swept_contacts(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                        const LineOfAction& line, const PlacedGears& gears, double reference,
                        std::vector<SceneContact>& contacts)
{
  const auto [low, high] =
      std::minmax_element(spec.swept_positions.begin(), spec.swept_positions.end());
  const double first = std::min(*low, reference), last = std::max(*high, reference);
  const SceneContact model = contacts.front(); // its Hertz estimate sets the default sizes
  const double fine_radius =
      spec.mesh.fine_radius > 0. ? spec.mesh.fine_radius : 1.5 * model.hertz_half_width;
  const double step = 0.5 * fine_radius;
  const double r_b1 = 0.5 * pair.pinion.base_diameter, r_b2 = 0.5 * pair.wheel.base_diameter;
  const double wheel_sense = gears.wheel.internal ? 1. : -1.;
  for (int j = -3; j <= 3; ++j)
  {
    // ℓ with ℓ + j·p_bt on the path of contact, within [first, last].
    const double from = std::max(first, pair.contact_start - j * pair.transverse_base_pitch);
    const double to = std::min(last, pair.contact_end - j * pair.transverse_base_pitch);
    if (!(to >= from))
      continue;
    const unsigned int n = static_cast<unsigned int>(std::ceil((to - from) / step)) + 1;
    for (unsigned int k = 0; k < n; ++k)
    {
      const double position = n == 1 ? from : from + (to - from) * k / (n - 1);
      const Eigen::Vector2d point = line.at(position + j * pair.transverse_base_pitch);
      const double turn = (position - reference) / r_b1;
      SceneContact on_pinion = model, on_wheel = model;
      on_pinion.point = place(point - gears.pinion_centre, gears.pinion_centre, -turn);
      on_wheel.point = place(point - gears.wheel_centre, gears.wheel_centre,
                             -wheel_sense * (position - reference) / r_b2);
      on_pinion.first_feature = on_wheel.first_feature = j;
      on_pinion.second_feature = on_wheel.second_feature = -j;
      contacts.push_back(on_pinion);
      contacts.push_back(on_wheel);
    }
  }
}

// A rounded tip edge's arc (ProfileSegment::tip_round) is contact surface like the flank: a
// contact line that leaves the path of contact at E (the pinion's tip form circle) or A (the
// wheel's) continues onto it under load. Where pair j's contacts over [first, last] come within
// the fine radius plus the arc's length of that end, foci along the arc of its tooth, at most
// half a fine radius apart, give the arc the contact size.
void add_tip_round_contacts(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                            const PlacedGears& gears, double first, double last,
                            std::vector<SceneContact>& contacts)
{
  const SceneContact model = contacts.front();
  const double fine_radius =
      spec.mesh.fine_radius > 0. ? spec.mesh.fine_radius : 1.5 * model.hertz_half_width;
  for (const bool wheel : {false, true})
  {
    const ToothProfile& nominal = wheel ? gears.wheel : gears.pinion;
    if (nominal.tip_form_radius == nominal.tip_radius)
      continue; // a sharp tip edge
    const double end = wheel ? pair.contact_start : pair.contact_end;
    for (int j = -3; j <= 3; ++j)
    {
      const double shift = j * pair.transverse_base_pitch;
      const int index = wheel ? mate_tooth(gears.wheel, j) : j;
      const ToothProfile& tooth =
          (wheel ? gears.wheel_contact_teeth : gears.pinion_contact_teeth).tooth(index);
      std::vector<Eigen::Vector2d> arc; // the loaded flank's arc, tip circle to flank
      double length = 0.;
      for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
      {
        const ProfileEdge edge = edge_between(tooth.points[i], tooth.points[i + 1]);
        if (edge.segment != ProfileSegment::tip_round || edge.side != loaded_side(tooth))
          continue;
        const Eigen::Vector2d a = tooth.points[i].position, b = tooth.points[i + 1].position;
        const unsigned int n = std::max(
            1u, static_cast<unsigned int>(std::ceil((b - a).norm() / (0.5 * fine_radius))));
        for (unsigned int k = arc.empty() ? 0 : 1; k <= n; ++k)
          arc.push_back(a + (b - a) * static_cast<double>(k) / n);
        length += (b - a).norm();
      }
      const double reach = fine_radius + length;
      if (arc.empty() || last + shift < end - reach || first + shift > end + reach)
        continue;
      const Eigen::Vector2d centre = wheel ? gears.wheel_centre : gears.pinion_centre;
      const double rotation =
          (wheel ? gears.wheel_rotation : gears.pinion_rotation) + index * tooth.angular_pitch;
      for (const Eigen::Vector2d& p : arc)
      {
        SceneContact focus = model;
        focus.point = place(p, centre, rotation);
        focus.first_feature = j;
        focus.second_feature = -j;
        contacts.push_back(focus);
      }
    }
  }
}

} // namespace detail

namespace
{
// Pinion tooth j and its mate as touching_separation sees them.
PairFlanks pair_flanks(const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                       const PlacedGears& gears, int j)
{
  PairFlanks flanks;
  const int mate = mate_tooth(gears.wheel, j);
  flanks.pinion_removal = [&gears, j](double roll)
  { return gears.pinion_teeth.loaded_flank_removal(j, roll); };
  flanks.wheel_removal = [&gears, mate](double roll)
  { return gears.wheel_teeth.loaded_flank_removal(mate, roll); };
  flanks.pinion_range = gears.pinion_teeth.roll_range();
  flanks.wheel_range = gears.wheel_teeth.roll_range();
  flanks.pinion_base_radius = 0.5 * std::abs(pair.pinion.base_diameter);
  flanks.wheel_base_radius = 0.5 * std::abs(pair.wheel.base_diameter);
  flanks.t2 = line.t2;
  flanks.internal = gears.wheel.internal;
  return flanks;
}

// The designed separation of a helical pair j whose mid-face section meets the line of action at
// `at` (m from T1): the smallest, along its contact line, of both flanks' profile removal at the
// point each section meets plus the lead removal of that section. A section z meets the pair at
// at + rate·(z − b/2) (gear_pair_helix.cc, contact_lines); only the sections whose point lies on
// the path of contact touch. Taking the mid-face section's profile removal plus the face's
// smallest lead removal instead (before 2026-12-03) adds the two minima of different sections:
// with profile and lead crowning it put the unloaded TE up to 1.7 µm above the meshed flanks'
// smallest gap on the built-in pair (tests/helical/test_helical_unloaded_error.cc).
std::optional<double> separation_along_line(const GearPairSceneSpec& spec,
                                            const kinematics::GearPairGeometry& pair,
                                            const LineOfAction& line, const PlacedGears& gears,
                                            double at, int j)
{
  const double rate = contact_shift_rate(pair), b = pair.common_face_width;
  const double z0 = model_section(pair);
  // The same margin as nearest_roll: the line of action meets both flanks inside it.
  const double margin = 0.01 * pair.transverse_base_pitch;
  const double za = z0 + (pair.contact_start + margin - at) / rate;
  const double ze = z0 + (pair.contact_end - margin - at) / rate;
  const double z_from = std::max(0., std::min(za, ze)), z_to = std::min(b, std::max(za, ze));
  if (!(z_to >= z_from))
    return std::nullopt;
  // Sections 1/2000 of the face apart, as smallest_lead_separation samples the lead alone: the
  // separation is smooth between the reliefs' kinks, which the samples straddle by at most
  // b/2000·tan β_b along the profile (6 µm on the built-in pair).
  constexpr int samples = 2000;
  const bool three_d = spec.mesh.dimension == 3;
  // Each section's flanks touch where their transverse gap is smallest (touching_separation),
  // at most its removal at the line, which bounds the sections worth that search.
  const PairFlanks flanks = pair_flanks(pair, line, gears, j);
  // (removal at the line + lead, roll, lead) of each section
  std::vector<std::tuple<double, double, double>> at_line;
  for (int i = 0; i <= samples; ++i)
  {
    const double z = z_from + (z_to - z_from) * i / samples;
    const double roll = at + rate * (z - z0);
    const double lead = three_d ? lead_removed_depth(spec.pinion_modifications.lead, z, b, true) +
                                      lead_removed_depth(spec.wheel_modifications.lead, z, b, true)
                                : 0.;
    at_line.emplace_back(flanks.pinion_removal(roll) +
                             flanks.wheel_removal(std::abs(roll - line.t2)) + lead,
                         roll, lead);
  }
  // The search lowers a section by at most β²R/2, β the largest slope of the gap across the
  // contact (both flanks' steepest removal per roll, times r_b/ρ) and R the largest relative
  // radius of the sections: sections whose removal at the line exceeds the smallest found by
  // more than that are not searched.
  const auto steepest =
      [](const std::function<double(double)>& removal, const FlankRollRange& range)
  {
    constexpr int steps = 1000;
    const double from = std::min(range.form, range.tip), to = std::max(range.form, range.tip);
    const double step = (to - from) / steps;
    double largest = 0.;
    for (int i = 0; i < steps; ++i)
      largest = std::max(
          largest, std::abs(removal(from + (i + 1) * step) - removal(from + i * step)) / step);
    return largest;
  };
  const double slope_1 = steepest(flanks.pinion_removal, flanks.pinion_range);
  const double slope_2 = steepest(flanks.wheel_removal, flanks.wheel_range);
  double lowered = 0.; // m, the most a section's search can lower it
  for (const auto& [removal, roll, lead] : at_line)
  {
    const double rho_1 = roll, rho_2 = std::abs(roll - line.t2);
    const double radius = 1. / (1. / rho_1 + (flanks.internal ? -1. : 1.) / rho_2);
    const double slope =
        slope_1 * flanks.pinion_base_radius / rho_1 + slope_2 * flanks.wheel_base_radius / rho_2;
    lowered = std::max(lowered, 0.5 * slope * slope * std::abs(radius));
  }
  std::sort(at_line.begin(), at_line.end());
  double smallest = std::numeric_limits<double>::max();
  for (const auto& [removal, roll, lead] : at_line)
  {
    if (removal - lowered >= smallest)
      break;
    smallest = std::min(smallest, lead + touching_separation(flanks, roll));
  }
  return smallest;
}

// The designed separation of each pair `pairs` at ℓ = `position` (the loaded flanks' removal at
// the kinematic contact point: both normals lie on the line of action there), lead
// modifications (3D) included.
std::vector<double> pair_separations(const GearPairSceneSpec& spec,
                                     const kinematics::GearPairGeometry& pair,
                                     const LineOfAction& line, const PlacedGears& gears,
                                     double position, const std::vector<int>& pairs)
{
  // Lead modifications (3D) add the smallest of the pair's summed lead removal over the face
  // width, the same for every pair (geometry/tooth_modification_lead.h).
  const double lead =
      spec.mesh.dimension == 3
          ? smallest_lead_separation(spec.pinion_modifications.lead, spec.wheel_modifications.lead,
                                     pair.common_face_width)
          : 0.;
  std::vector<double> separations;
  for (const int j : pairs)
  {
    double at = position + j * pair.transverse_base_pitch;
    if (is_helical_pair(pair))
    {
      if (const auto along = separation_along_line(spec, pair, line, gears, at, j))
      {
        separations.push_back(*along);
        continue;
      }
      // A pair whose line misses the path in every section (within the margin): where it
      // touches nearest to the mid-face section.
      at += nearest_roll(pair, position, j);
    }
    separations.push_back(touching_separation(pair_flanks(pair, line, gears, j), at) + lead);
  }
  return separations;
}

} // namespace

namespace detail
{
// The designed separation of every pair in contact and its smallest value, the unloaded
// transmission error.
void set_unloaded_transmission_error(const GearPairSceneSpec& spec,
                                     const kinematics::GearPairGeometry& pair,
                                     const LineOfAction& line, const PlacedGears& gears,
                                     GearPairScene& scene)
{
  scene.pair_separation =
      pair_separations(spec, pair, line, gears, scene.reference_position, scene.contact_pairs);
  scene.unloaded_transmission_error =
      scene.pair_separation.empty()
          ? 0.
          : *std::min_element(scene.pair_separation.begin(), scene.pair_separation.end());
}

} // namespace detail

std::vector<double> unloaded_transmission_errors(const GearPairSceneSpec& given,
                                                 const std::vector<double>& positions)
{
  const GearPairSceneSpec spec = transverse_section_spec(given);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const PlacedGears gears = generate_teeth(spec, pair);
  const LineOfAction line = line_of_action(pair);
  std::vector<double> errors;
  for (const double position : positions)
  {
    const std::vector<double> separations =
        pair_separations(spec, pair, line, gears, position,
                         is_helical_pair(pair) ? pairs_across_face(pair, position)
                                               : pairs_in_contact(pair, position));
    if (separations.empty())
      throw InputError(scene_field::swept_positions, "no tooth pair is in contact at " +
                                                         format_number(position * 1e3, 6) +
                                                         " mm along the line of action");
    errors.push_back(*std::min_element(separations.begin(), separations.end()));
  }
  return errors;
}
} // namespace gearstiff::geometry
