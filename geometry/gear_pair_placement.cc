// The gear-pair scene's placement: where the reference pair touches along the line of action,
// which pairs are in contact (and carry, with faults), the gears turned into mesh, and the window
// of modelled teeth.
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/gear_pair_internal.h"
#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_fault.h"
#include "geometry/tooth_modification_lead.h"
#include "kinematics/fields.h"

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

namespace gearstiff::geometry
{
using namespace detail;

namespace
{
// ψ_b: the loaded flank (side s) of a tooth on the +x axis lies at polar angle
// s·(ψ_b − σ·inv(α_r)), cos α_r = r_b/r. Recovered from the profile points, so the placement below
// relies only on the profile actually meshed; points that disagree mean the profile is not
// the involute of its base circle, and placing it would produce a wrong gap.
double base_half_angle(const ToothProfile& tooth)
{
  std::vector<double> values;
  for (const auto& point : tooth.points)
    if (point.segment == ProfileSegment::flank && point.side == loaded_side(tooth))
    {
      const double r = point.position.norm();
      if (r <= tooth.base_radius * (1. + 1e-12))
        continue;
      values.push_back(loaded_side(tooth) * std::atan2(point.position.y(), point.position.x()) +
                       involute_sign(tooth) *
                           kinematics::involute(std::acos(tooth.base_radius / r)));
    }
  if (values.empty())
    throw SolverFailure("gear scene placement", "the tooth profile has no involute flank points");
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  // 1e-9 rad is 25 nm on the pinion base circle, far below any contact size.
  if (*highest - *lowest > 1e-9)
    throw SolverFailure("gear scene placement",
                        "the flank points do not follow the involute of the base circle "
                        "(spread " +
                            std::to_string(*highest - *lowest) + " rad)");
  double sum = 0.;
  for (const double v : values)
    sum += v;
  return sum / values.size();
}

// Rotation (rad, CCW) that puts the loaded flank of tooth 0 of a gear centred at `centre`
// through `point`.
double placing_rotation(const ToothProfile& tooth, const Eigen::Vector2d& centre,
                        const Eigen::Vector2d& point)
{
  const Eigen::Vector2d d = point - centre;
  const double involute = kinematics::involute(std::acos(tooth.base_radius / d.norm()));
  return std::atan2(d.y(), d.x()) -
         loaded_side(tooth) * (base_half_angle(tooth) - involute_sign(tooth) * involute);
}

} // namespace

namespace detail
{
Eigen::Vector2d place(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double rotation)
{
  return centre + Eigen::Rotation2Dd(rotation) * p;
}

// Position of the reference pair along the line of action (m from T1).
double reference_position(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair)
{
  const double b = pair.single_contact_start(), d = pair.single_contact_end();
  switch (spec.position)
  {
  case PairPosition::single:
    if (!(d > b))
      throw InputError(scene_field::position,
                       "'single': the pair has no single-contact zone (contact ratio " +
                           std::to_string(pair.transverse_contact_ratio) + ")");
    return (pair.pitch_point >= b && pair.pitch_point <= d) ? pair.pitch_point : 0.5 * (b + d);
  case PairPosition::double_pair:
    return 0.5 * (pair.contact_start + b); // B = E − p_bt ends the first double zone
  case PairPosition::roll_angle:
    break;
  }
  const double radius = 0.5 * pair.pinion.base_diameter;
  // The ends are printed to 6 decimals of a degree: a roll angle typed back from the message
  // (within half a unit of its last digit) is that end. With 6 significant digits "10.9091"
  // was printed and then refused.
  const double printed = 0.5e-6 * M_PI / 180.;
  const double start = pair.contact_start / radius, end = pair.contact_end / radius;
  if (std::abs(spec.pinion_roll_angle - start) <= printed)
    return pair.contact_start;
  if (std::abs(spec.pinion_roll_angle - end) <= printed)
    return pair.contact_end;
  const double position = spec.pinion_roll_angle * radius;
  if (position < pair.contact_start - path_tolerance ||
      position > pair.contact_end + path_tolerance)
  {
    std::ostringstream range;
    range << std::fixed << std::setprecision(6) << "must lie on the path of contact, between "
          << start * 180 / M_PI << " and " << end * 180 / M_PI << " degrees";
    throw InputError(scene_field::pinion_roll_angle, range.str());
  }
  return position;
}

} // namespace detail

namespace
{
// Window of `count` consecutive pair indices centred on the contacting ones; an even count
// takes the extra tooth on the approach side, where the next pair enters under load.
int window_start(const std::vector<int>& contacting, unsigned int count)
{
  double centre = 0.;
  for (const int j : contacting)
    centre += j;
  centre /= contacting.size();
  return static_cast<int>(std::floor(centre - 0.5 * (count - 1.) + 1e-9));
}

} // namespace

namespace detail
{
// The pairs j inside the path of contact (A, E). A pair at an end (to round-off) touches only
// at a tip corner, which the flank outlines cannot place: it is leaving or entering contact
// and carries no load.
std::vector<int> pairs_in_contact(const kinematics::GearPairGeometry& pair, double reference)
{
  std::vector<int> contacting;
  for (int j = -3; j <= 3; ++j)
  {
    const double position = reference + j * pair.transverse_base_pitch;
    if (position > pair.contact_start + path_tolerance &&
        position < pair.contact_end - path_tolerance)
      contacting.push_back(j);
  }
  if (contacting.empty())
    throw SolverFailure("gear scene placement", "no pair in contact at the chosen position");
  return contacting;
}

LineOfAction line_of_action(const kinematics::GearPairGeometry& pair)
{
  const double alpha = pair.working_pressure_angle;
  const double base_radius_1 = 0.5 * pair.pinion.base_diameter;
  return {base_radius_1 * Eigen::Vector2d(std::cos(alpha), -std::sin(alpha)),
          Eigen::Vector2d(std::sin(alpha), std::cos(alpha)),
          pair.spec.wheel.internal ? -pair.line_of_action_length : pair.line_of_action_length};
}

// The wheel tooth that meshes pinion tooth j: −j on an external wheel (it turns the other
// way), +j on a ring (it turns with the pinion).
int mate_tooth(const ToothProfile& wheel, int j)
{
  return wheel.internal ? j : -j;
}

} // namespace detail

namespace
{
// Rolling sweeps: the pairs in contact at the scene's position or at one of the swept ones.
// The pairs that touch with the reference pair at ℓ: across the face for a helical pair.
std::vector<int> touching_pairs(const kinematics::GearPairGeometry& pair, double reference)
{
  return is_helical_pair(pair) ? pairs_across_face(pair, reference)
                               : pairs_in_contact(pair, reference);
}

std::vector<int> swept_pairs(const GearPairSceneSpec& spec,
                             const kinematics::GearPairGeometry& pair,
                             const std::vector<int>& contact_pairs)
{
  std::vector<int> pairs = contact_pairs;
  for (const double position : spec.swept_positions)
  {
    if (position < pair.contact_start - path_tolerance ||
        position > pair.contact_end + path_tolerance)
      throw InputError(scene_field::swept_positions,
                       "a swept position lies off the path of contact");
    for (const int j : touching_pairs(pair, position))
      pairs.push_back(j);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace

std::vector<int> gear_pairs_in_contact(const kinematics::GearPairGeometry& pair, double position)
{
  return pairs_in_contact(pair, position);
}

std::vector<int> gear_pairs_across_face(const kinematics::GearPairGeometry& pair, double position)
{
  return touching_pairs(pair, position);
}

namespace
{
// -, the most pairs that touch across a helical face at one position of the mesh cycle (the
// pairs repeat with the transverse base pitch): 24 reference positions a pitch apart/24, finer
// than the quarter pitch at which face_positions samples each face.
unsigned int most_pairs_across_face(const kinematics::GearPairGeometry& pair)
{
  constexpr int samples = 24;
  std::size_t most = 0;
  for (int k = 0; k < samples; ++k)
    most =
        std::max(most, pairs_across_face(pair, pair.contact_start +
                                                   (k + 0.5) / samples * pair.transverse_base_pitch)
                           .size());
  return static_cast<unsigned int>(most);
}
} // namespace

GearPairSceneSpec with_teeth_modelled(const GearPairSceneSpec& given)
{
  if (!given.pinion_teeth_follow_pairs && !given.wheel_teeth_follow_pairs)
    return given;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(given.pair);
  const std::vector<int> swept =
      swept_pairs(given, pair, touching_pairs(pair, reference_position(given, pair)));
  // A helical sweep's positions model the same teeth: a tooth more at one position only would
  // step k(θ) by the body's own stiffness.
  const unsigned int needed = std::max(static_cast<unsigned int>(swept.size()),
                                       is_helical_pair(pair) ? most_pairs_across_face(pair) : 0u);
  GearPairSceneSpec spec = given;
  if (spec.pinion_teeth_follow_pairs)
    spec.pinion_teeth_modelled = std::max(spec.pinion_teeth_modelled, needed);
  if (spec.wheel_teeth_follow_pairs)
    spec.wheel_teeth_modelled = std::max(spec.wheel_teeth_modelled, needed);
  return spec;
}

Eigen::Vector2d line_of_action_point(const kinematics::GearPairGeometry& pair, double position)
{
  return line_of_action(pair).at(position);
}

PairPosition parse_pair_position(const std::string& text, const std::string& parameter)
{
  if (text == "single")
    return PairPosition::single;
  if (text == "double")
    return PairPosition::double_pair;
  if (text == "roll angle")
    return PairPosition::roll_angle;
  throw InputError(parameter, "'" + text + "' is not one of single, double, roll angle");
}

std::string to_string(PairPosition position)
{
  switch (position)
  {
  case PairPosition::single:
    return "single";
  case PairPosition::double_pair:
    return "double";
  case PairPosition::roll_angle:
    break;
  }
  return "roll angle";
}

namespace
{
bool has_tooth_faults(const GearModifications& modifications)
{
  for (const auto& [index, list] : modifications.by_tooth)
    if (has_faults(list))
      return true;
  return false;
}

// The pairs in contact whose loaded flanks both exist at their contact point: a broken faulty
// tooth, or one chipped where the pair would touch, drops its pair (issue 31: the other pairs
// carry alone). None left: the mesh has lost contact there, and no stiffness exists.
std::vector<int> carrying_pairs(const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                                const PlacedGears& gears, double reference,
                                const std::vector<int>& pairs)
{
  std::vector<int> carrying;
  for (const int j : pairs)
  {
    const double position = reference + j * pair.transverse_base_pitch;
    const int mate = mate_tooth(gears.wheel, j);
    if (flank_carries(gears.pinion_teeth.modifications_of(j), gears.pinion, position) &&
        flank_carries(gears.wheel_teeth.modifications_of(mate), gears.wheel,
                      std::abs(position - line.t2)))
      carrying.push_back(j);
  }
  if (carrying.empty())
    throw SolverFailure(
        "gear scene placement",
        "loss of contact: every pair in contact at this position has a broken or "
        "chipped flank at its contact point (no tooth carries, no stiffness exists)");
  return carrying;
}

} // namespace

namespace detail
{
// Position of the reference pair, the pairs in contact there (and over a rolling sweep), and
// whether the modelled teeth can hold them.
void locate_pairs(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                  const LineOfAction& line, const PlacedGears& gears, GearPairScene& scene)
{
  const bool faults =
      has_tooth_faults(spec.pinion_modifications) || has_tooth_faults(spec.wheel_modifications);
  // A cracked scene rolls like a healthy one (`sweep mesh = once`; geometry/tooth_fault.h).
  if (faults && !spec.swept_positions.empty() &&
      !(flanks_whole(spec.pinion_modifications) && flanks_whole(spec.wheel_modifications)))
    throw InputError(scene_field::swept_positions,
                     "a scene with a broken, chipped or spalled tooth is meshed per position (it "
                     "changes which pairs carry from one position to the next)");
  scene.reference_position = reference_position(spec, pair);
  scene.contact_pairs = touching_pairs(pair, scene.reference_position);
  if (faults)
    scene.contact_pairs =
        carrying_pairs(pair, line, gears, scene.reference_position, scene.contact_pairs);
  scene.swept_pairs = swept_pairs(spec, pair, scene.contact_pairs);
  for (const auto& [count, field] :
       {std::pair{spec.pinion_teeth_modelled, scene_field::pinion_teeth_modelled},
        std::pair{spec.wheel_teeth_modelled, scene_field::wheel_teeth_modelled}})
    if (count < scene.swept_pairs.size())
      throw InputError(field,
                       "must be at least the number of pairs in contact (" +
                           std::to_string(scene.swept_pairs.size()) + ") at this position" +
                           (is_helical_pair(pair) ? " (across the face)" : "") +
                           (spec.swept_positions.empty() ? "" : " or one the sweep turns to") +
                           "; auto models them all");
}

Eigen::Vector2d wheel_centre(const kinematics::GearPairGeometry& pair)
{
  return {pair.spec.wheel.internal ? -pair.centre_distance : pair.centre_distance, 0.};
}

// Placement: the loaded flanks of pair 0 through the reference point. An external wheel sits
// beyond the pitch point, a ring's centre on the other side of the pinion's (the pitch point lies
// on the ring's pitch circle, outside the pinion).
void place_gears(const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                 double reference, PlacedGears& gears)
{
  const Eigen::Vector2d reference_point = line.at(reference);
  gears.pinion_centre = Eigen::Vector2d(0., 0.);
  gears.wheel_centre = wheel_centre(pair);
  gears.pinion_rotation = placing_rotation(gears.pinion, gears.pinion_centre, reference_point);
  gears.wheel_rotation = placing_rotation(gears.wheel, gears.wheel_centre, reference_point);
}

} // namespace detail

namespace
{
// A faulty tooth outside the modelled teeth would be silently healthy: refused by its index.
void check_faulty_teeth_modelled(const GearModifications& modifications, int first, int last,
                                 bool wheel)
{
  for (const auto& [index, list] : modifications.by_tooth)
    if (has_faults(list) && (index < first || index > last))
      throw InputError(kinematics::field::gear(wheel, "faulty_tooth"),
                       "tooth " + std::to_string(index) + " is not among the modelled teeth (" +
                           std::to_string(first) + " to " + std::to_string(last) +
                           ") at this position");
}

} // namespace

namespace detail
{
ModelWindows model_windows(const GearPairSceneSpec& spec, const PlacedGears& gears,
                           GearPairScene& scene)
{
  ModelWindows w;
  w.pinion_first = window_start(scene.swept_pairs, spec.pinion_teeth_modelled);
  w.pinion_last = w.pinion_first + static_cast<int>(spec.pinion_teeth_modelled) - 1;
  w.wheel_first_pair = window_start(scene.swept_pairs, spec.wheel_teeth_modelled);
  w.wheel_last_pair = w.wheel_first_pair + static_cast<int>(spec.wheel_teeth_modelled) - 1;
  for (int j = std::max(w.pinion_first, w.wheel_first_pair);
       j <= std::min(w.pinion_last, w.wheel_last_pair); ++j)
    scene.modelled_pairs.push_back(j);
  const int a = mate_tooth(gears.wheel, w.wheel_first_pair);
  const int b = mate_tooth(gears.wheel, w.wheel_last_pair);
  w.wheel_first = std::min(a, b);
  w.wheel_last = std::max(a, b);
  check_faulty_teeth_modelled(spec.pinion_modifications, w.pinion_first, w.pinion_last, false);
  check_faulty_teeth_modelled(spec.wheel_modifications, w.wheel_first, w.wheel_last, true);
  return w;
}

} // namespace detail

std::vector<int> carrying_gear_pairs(const GearPairSceneSpec& given, double position)
{
  const GearPairSceneSpec spec = transverse_section_spec(given);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const PlacedGears gears = generate_teeth(spec, pair);
  try
  {
    return carrying_pairs(pair, line_of_action(pair), gears, position,
                          pairs_in_contact(pair, position));
  }
  catch (const SolverFailure&)
  {
    return {};
  }
}
} // namespace gearstiff::geometry
