#include "geometry/scene_gear_pair.h"

#include "geometry/involute_tooth.h"
#include "errors/errors.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

namespace gearstiff::geometry
{
namespace
{
constexpr const char* section = "Gear pair scene/";

// Contacts closer than this to the ends A, E of the path of contact still count (m): the
// zone ends come from the same floating-point formulas as the positions.
constexpr double path_tolerance = 1e-9;

InvoluteToothSpec tooth_spec(const kinematics::GearSpec& gear,
                             const kinematics::GearGeometry& derived)
{
  InvoluteToothSpec spec;
  spec.teeth = gear.teeth;
  spec.module = gear.normal_module;
  spec.pressure_angle = gear.pressure_angle;
  spec.profile_shift = gear.profile_shift;
  spec.tip_diameter = derived.tip_diameter;
  spec.internal = gear.internal;
  spec.cutter_addendum = gear.dedendum_coefficient;
  spec.cutter_dedendum = gear.addendum_coefficient;
  spec.cutter_tip_radius = gear.root_radius_coefficient;
  spec.gear_addendum = gear.addendum_coefficient;
  spec.required_form_diameter = derived.active_profile_start;
  return spec;
}

bool is_flank(const ProfilePoint& point)
{
  return point.segment == ProfileSegment::flank || point.segment == ProfileSegment::relief;
}

// ψ_b: an involute flank on side +1 of a tooth on the +x axis lies at polar angle
// ψ_b − inv(α_r), cos α_r = r_b/r. Recovered from the profile points, so the placement below
// relies only on the profile actually meshed; points that disagree mean the profile is not
// the involute of its base circle, and placing it would produce a wrong gap.
double base_half_angle(const ToothProfile& tooth)
{
  std::vector<double> values;
  for (const auto& point : tooth.points)
    if (point.segment == ProfileSegment::flank && point.side == +1)
    {
      const double r = point.position.norm();
      if (r <= tooth.base_radius * (1. + 1e-12))
        continue;
      values.push_back(std::atan2(point.position.y(), point.position.x()) +
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

// Rotation (rad, CCW) that puts the loaded flank (side +1) of tooth 0 of a gear centred at
// `centre` through `point`.
double placing_rotation(const ToothProfile& tooth, const Eigen::Vector2d& centre,
                        const Eigen::Vector2d& point)
{
  const Eigen::Vector2d d = point - centre;
  return std::atan2(d.y(), d.x()) - base_half_angle(tooth) +
         kinematics::involute(std::acos(tooth.base_radius / d.norm()));
}

Eigen::Vector2d place(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double rotation)
{
  return centre + Eigen::Rotation2Dd(rotation) * p;
}

// Parameter t of the intersection of origin + t·direction with the loaded flank (side +1)
// polyline of the given tooth, nearest to t = 0; none if the line misses the flank.
std::optional<double> flank_intersection(const ToothProfile& tooth, const Eigen::Vector2d& centre,
                                         double rotation, const Eigen::Vector2d& origin,
                                         const Eigen::Vector2d& direction)
{
  std::optional<double> best;
  const ProfilePoint* previous = nullptr;
  for (const auto& point : tooth.points)
  {
    if (!(is_flank(point) && point.side == +1))
    {
      previous = nullptr;
      continue;
    }
    if (previous != nullptr)
    {
      const Eigen::Vector2d a = place(previous->position, centre, rotation);
      const Eigen::Vector2d b = place(point.position, centre, rotation);
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
    previous = &point;
  }
  return best;
}

// The outline pieces of teeth `first`..`last` (indices CCW from tooth 0), placed. A new piece
// starts wherever the segment or side changes, so kinks (flank to tip, relief start) stay
// kinks and each piece carries one boundary id.
std::vector<BoundaryPiece> teeth_pieces(const ToothProfile& tooth, const Eigen::Vector2d& centre,
                                        double rotation, int first, int last, int flank_id,
                                        bool both_flanks)
{
  std::vector<BoundaryPiece> pieces;
  const auto id_of = [&](const ProfilePoint& p)
  { return (is_flank(p) && (p.side == +1 || both_flanks)) ? flank_id : 0; };
  for (int k = first; k <= last; ++k)
  {
    const double angle = rotation + k * tooth.angular_pitch;
    const ProfilePoint* run_start = nullptr;
    for (std::size_t i = 0; i < tooth.points.size(); ++i)
    {
      const ProfilePoint& point = tooth.points[i];
      const Eigen::Vector2d position = place(point.position, centre, angle);
      const bool new_run = run_start == nullptr || point.segment != run_start->segment ||
                           point.side != run_start->side;
      if (new_run)
      {
        if (!pieces.empty() && i > 0)
          pieces.back().points.push_back(position);
        if (i + 1 < tooth.points.size())
        {
          pieces.emplace_back();
          pieces.back().kind = CurveKind::spline;
          pieces.back().boundary_id = id_of(point);
          pieces.back().points.push_back(position);
        }
        run_start = &point;
      }
      else
        pieces.back().points.push_back(position);
    }
  }
  // Consecutive teeth share their gap-middle point: the next tooth's first point starts a
  // piece that duplicates the previous piece's end, which is where it belongs.
  return pieces;
}

struct GearBodySpec
{
  std::string name;
  int material_id, bore_id, flank_id, cut_id;
  double bore_radius;
};

PlanarBody gear_body(const GearBodySpec& body_spec, const ToothProfile& tooth,
                     const Eigen::Vector2d& centre, double rotation, int first, int last,
                     RimModel rim, bool both_flanks)
{
  PlanarBody body;
  body.name = body_spec.name;
  body.material_id = body_spec.material_id;
  body.outer.pieces =
      teeth_pieces(tooth, centre, rotation, first, last, body_spec.flank_id, both_flanks);
  const double root_radius = tooth.points.front().position.norm();
  const double start_angle = rotation + (first - 0.5) * tooth.angular_pitch;
  const double end_angle = rotation + (last + 0.5) * tooth.angular_pitch;
  const Eigen::Vector2d outline_start = body.outer.pieces.front().points.front();
  const bool all_teeth = (last - first + 1) == tooth.teeth;
  if (rim == RimModel::sector)
  {
    const auto at = [&](double radius, double angle) -> Eigen::Vector2d
    { return centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)); };
    BoundaryPiece cut_down;
    cut_down.kind = CurveKind::straight;
    cut_down.boundary_id = body_spec.cut_id;
    cut_down.points = {body.outer.pieces.back().points.back(),
                       at(body_spec.bore_radius, end_angle)};
    body.outer.pieces.push_back(cut_down);
    for (auto& piece :
         arc_pieces(centre, body_spec.bore_radius, end_angle, start_angle, body_spec.bore_id))
      body.outer.pieces.push_back(piece);
    BoundaryPiece cut_up = cut_down;
    cut_up.points = {body.outer.pieces.back().points.back(), outline_start};
    body.outer.pieces.push_back(cut_up);
  }
  else
  {
    if (!all_teeth)
      for (auto& piece : arc_pieces(centre, root_radius, end_angle, start_angle + 2. * M_PI,
                                    scene_ids::free_surface))
        body.outer.pieces.push_back(piece);
    body.holes.push_back(circle_loop(centre, body_spec.bore_radius, body_spec.bore_id));
  }
  // The loop closes on the first point exactly (rotations by 2π are not bit-exact).
  body.outer.pieces.back().points.back() = outline_start;
  return body;
}

// Position of the reference pair along the line of action (m from T1).
double reference_position(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair)
{
  const double b = pair.single_contact_start(), d = pair.single_contact_end();
  if (spec.position == "single")
  {
    if (!(d > b))
      throw InputError(std::string(section) + "position",
                       "'single': the pair has no single-contact zone (contact ratio " +
                           std::to_string(pair.transverse_contact_ratio) + ")");
    return (pair.pitch_point >= b && pair.pitch_point <= d) ? pair.pitch_point : 0.5 * (b + d);
  }
  if (spec.position == "double")
    return 0.5 * (pair.contact_start + b); // B = E − p_bt ends the first double zone
  if (spec.position == "roll angle")
  {
    const double radius = 0.5 * pair.pinion.base_diameter;
    const double position = spec.pinion_roll_angle * radius;
    if (position < pair.contact_start - path_tolerance ||
        position > pair.contact_end + path_tolerance)
    {
      std::ostringstream range;
      range << "must lie on the path of contact, between "
            << pair.contact_start / radius * 180 / M_PI << " and "
            << pair.contact_end / radius * 180 / M_PI << " degrees";
      throw InputError(std::string(section) + "pinion roll angle", range.str());
    }
    return position;
  }
  throw InputError(std::string(section) + "position",
                   "'" + spec.position + "' is not one of single, double, roll angle");
}

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

RimModel parse_rim_model(const std::string& text, const std::string& parameter)
{
  if (text == "sector")
    return RimModel::sector;
  if (text == "full")
    return RimModel::full;
  throw InputError(parameter, "'" + text + "' is not one of sector, full");
}

SceneInfo write_gear_pair_scene(const GearPairSceneSpec& spec, const std::string& file)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string p = section;

  // Everything is checked before gmsh runs: the pair itself (interference, backlash, contact
  // ratio) by the kinematics, the scene's own extent here.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  if (spec.pair.wheel.internal)
    throw InputError(kinematics::gear_parameter_name(true, "internal"),
                     "the gear-pair scene models external pairs only");
  if (spec.pair.pinion.helix_angle != 0. || spec.pair.wheel.helix_angle != 0.)
    throw InputError(kinematics::gear_parameter_name(false, "helix angle"),
                     "the gear-pair scene models spur gears only (helix angle 0)");
  if (!(spec.pinion_torque > 0.))
    throw InputError(p + "pinion torque", "must be positive");
  if (!(spec.young_modulus > 0.))
    throw InputError(p + "Young's modulus", "must be positive");
  if (!(spec.poisson_ratio > 0. && spec.poisson_ratio < 0.5))
    throw InputError(p + "Poisson's ratio", "must lie in (0, 0.5)");

  const ToothProfile pinion_tooth =
      generate_involute_tooth(tooth_spec(spec.pair.pinion, pair.pinion), spec.resolution);
  const ToothProfile wheel_tooth =
      generate_involute_tooth(tooth_spec(spec.pair.wheel, pair.wheel), spec.resolution);

  const auto bore_radius = [&](double given, const kinematics::GearSpec& gear,
                               const ToothProfile& tooth, const std::string& name)
  {
    const double radius = given > 0. ? given : 0.5 * gear.bore_diameter;
    const std::string parameter =
        given > 0. ? p + name
                   : kinematics::gear_parameter_name(&gear == &spec.pair.wheel, "bore diameter");
    const double root_radius = tooth.points.front().position.norm();
    if (!(radius > 0.))
      throw InputError(parameter, "must be positive (no bore given for the gear)");
    // The rim under the root must keep at least one module of material, or the mesh of the
    // rim degenerates into a sliver.
    if (radius > root_radius - gear.normal_module)
      throw InputError(parameter, "leaves a rim thinner than one module under the root circle "
                                  "(root radius " +
                                      std::to_string(root_radius * 1e3) + " mm)");
    return radius;
  };
  const double pinion_bore =
      bore_radius(spec.pinion_bore_radius, spec.pair.pinion, pinion_tooth, "pinion bore radius");
  const double wheel_bore =
      bore_radius(spec.wheel_bore_radius, spec.pair.wheel, wheel_tooth, "wheel bore radius");

  const auto check_count = [&](unsigned int count, unsigned int teeth, const std::string& name)
  {
    const unsigned int limit = spec.rim == RimModel::sector ? teeth - 1 : teeth;
    if (count < 1 || count > limit)
      throw InputError(p + name, "must lie between 1 and " + std::to_string(limit) +
                                     (spec.rim == RimModel::sector ? " (sector rim)" : ""));
  };
  check_count(spec.pinion_teeth_modelled, spec.pair.pinion.teeth, "pinion teeth modelled");
  check_count(spec.wheel_teeth_modelled, spec.pair.wheel.teeth, "wheel teeth modelled");

  // Line of action (header comment): T1 on the pinion base circle, direction u.
  const double alpha = pair.working_pressure_angle;
  const double base_radius_1 = 0.5 * pair.pinion.base_diameter;
  const Eigen::Vector2d pinion_centre(0., 0.), wheel_centre(pair.centre_distance, 0.);
  const Eigen::Vector2d u(std::sin(alpha), std::cos(alpha));
  const Eigen::Vector2d t1 = base_radius_1 * Eigen::Vector2d(std::cos(alpha), -std::sin(alpha));
  const Eigen::Vector2d t2 = t1 + pair.line_of_action_length * u;

  const double reference = reference_position(spec, pair);
  std::vector<int> contacting;
  for (int j = -3; j <= 3; ++j)
  {
    const double position = reference + j * pair.transverse_base_pitch;
    // A pair at an end of the path (A or E, to round-off) touches only at a tip corner, which
    // the flank outlines cannot place: it is leaving or entering contact and carries no load.
    if (position > pair.contact_start + path_tolerance &&
        position < pair.contact_end - path_tolerance)
      contacting.push_back(j);
  }
  if (contacting.empty())
    throw SolverFailure("gear scene placement", "no pair in contact at the chosen position");
  for (const auto& [count, name] : {std::pair{spec.pinion_teeth_modelled, "pinion teeth modelled"},
                                    std::pair{spec.wheel_teeth_modelled, "wheel teeth modelled"}})
    if (count < contacting.size())
      throw InputError(p + name, "must be at least the number of pairs in contact (" +
                                     std::to_string(contacting.size()) + ") at this position");

  const Eigen::Vector2d reference_point = t1 + reference * u;
  const double pinion_rotation = placing_rotation(pinion_tooth, pinion_centre, reference_point);
  const double wheel_rotation = placing_rotation(wheel_tooth, wheel_centre, reference_point);

  // Predicted contacts, each with its measured initial gap between the placed flank outlines.
  const double face_width = std::min(spec.pair.pinion.face_width, spec.pair.wheel.face_width);
  const double normal_force = spec.pinion_torque / base_radius_1 / contacting.size();
  std::vector<SceneContact> contacts;
  for (const int j : contacting)
  {
    SceneContact contact;
    const double position = reference + j * pair.transverse_base_pitch;
    contact.point = t1 + position * u;
    contact.normal = u;
    contact.first_curvature_radius = position;
    contact.second_curvature_radius = pair.line_of_action_length - position;
    contact.normal_force = normal_force;
    contact.first_feature = j;
    contact.second_feature = -j;
    if (!(contact.first_curvature_radius > 0. && contact.second_curvature_radius > 0.))
      throw SolverFailure("gear scene placement", "contact outside the line of action");
    contact.hertz_half_width = hertz_half_width(
        normal_force / face_width, contact.first_curvature_radius, contact.second_curvature_radius,
        spec.young_modulus, spec.poisson_ratio, spec.young_modulus, spec.poisson_ratio);
    const auto on_pinion =
        flank_intersection(pinion_tooth, pinion_centre,
                           pinion_rotation + j * pinion_tooth.angular_pitch, contact.point, u);
    const auto on_wheel =
        flank_intersection(wheel_tooth, wheel_centre,
                           wheel_rotation - j * wheel_tooth.angular_pitch, contact.point, u);
    if (!on_pinion || !on_wheel)
      throw SolverFailure("gear scene placement",
                          "the line of action misses a flank of pair " + std::to_string(j));
    contact.gap = *on_wheel - *on_pinion;
    contacts.push_back(contact);
  }

  const int pinion_first = window_start(contacting, spec.pinion_teeth_modelled);
  const int pinion_last = pinion_first + static_cast<int>(spec.pinion_teeth_modelled) - 1;
  const int wheel_first_pair = window_start(contacting, spec.wheel_teeth_modelled);
  const int wheel_last_pair = wheel_first_pair + static_cast<int>(spec.wheel_teeth_modelled) - 1;

  PlanarModel model;
  model.bodies.push_back(gear_body({"pinion body", scene_ids::pinion_body, scene_ids::pinion_bore,
                                    scene_ids::pinion_flanks, scene_ids::pinion_cuts, pinion_bore},
                                   pinion_tooth, pinion_centre, pinion_rotation, pinion_first,
                                   pinion_last, spec.rim, spec.both_flanks));
  model.bodies.push_back(gear_body({"wheel body", scene_ids::wheel_body, scene_ids::wheel_bore,
                                    scene_ids::wheel_flanks, scene_ids::wheel_cuts, wheel_bore},
                                   wheel_tooth, wheel_centre, wheel_rotation, -wheel_last_pair,
                                   -wheel_first_pair, spec.rim, spec.both_flanks));
  model.boundary_names = {{scene_ids::pinion_bore, "pinion bore"},
                          {scene_ids::wheel_bore, "wheel bore"},
                          {scene_ids::pinion_flanks, "pinion candidate flanks"},
                          {scene_ids::wheel_flanks, "wheel candidate flanks"}};
  if (spec.rim == RimModel::sector)
  {
    model.boundary_names[scene_ids::pinion_cuts] = "pinion sector cuts";
    model.boundary_names[scene_ids::wheel_cuts] = "wheel sector cuts";
  }

  // The rims only carry the tooth loads to the bore: their cells may grow with depth below
  // the root circle, which keeps a thin-rimmed wheel sector from dominating the cell count.
  const double pinion_root = pinion_tooth.points.front().position.norm();
  const double wheel_root = wheel_tooth.points.front().position.norm();
  const auto depth_below_root = [=](const Eigen::Vector2d& x)
  {
    return std::max(pinion_root - (x - pinion_centre).norm(),
                    wheel_root - (x - wheel_centre).norm());
  };
  SceneInfo info = mesh_scene(model, contacts, spec.mesh, face_width, file, depth_below_root);
  info.kind = "gear pair";
  info.first_centre = pinion_centre;
  info.second_centre = wheel_centre;
  info.first_rotation = pinion_rotation;
  info.second_rotation = wheel_rotation;
  info.reference_line = {t1, t2};
  const auto add = [&](const std::string& key, double value, const std::string& unit,
                       const std::string& description) {
    info.quantities.push_back({key, value, unit, description});
  };
  add("centre_distance", pair.centre_distance, "m", "centre distance a_w");
  add("working_pressure_angle", alpha, "rad", "working pressure angle α_wt");
  add("reference_contact_position", reference, "m", "reference contact, distance from T1");
  add("pinion_roll_angle", reference / base_radius_1, "rad", "pinion roll angle ℓ/r_b1");
  add("pairs_in_contact", contacting.size(), "-", "tooth pairs in contact");
  add("pinion_teeth_modelled", spec.pinion_teeth_modelled, "-", "pinion teeth in the scene");
  add("wheel_teeth_modelled", spec.wheel_teeth_modelled, "-", "wheel teeth in the scene");
  add("pinion_bore_radius", pinion_bore, "m", "pinion bore radius");
  add("wheel_bore_radius", wheel_bore, "m", "wheel bore radius");
  add("pinion_root_radius", pinion_root, "m", "pinion root radius (rim outer radius)");
  add("wheel_root_radius", wheel_root, "m", "wheel root radius (rim outer radius)");
  add("pinion_tip_radius", pinion_tooth.tip_radius, "m", "pinion tip radius");
  add("wheel_tip_radius", wheel_tooth.tip_radius, "m", "wheel tip radius");
  add("pinion_sector_angle",
      spec.rim == RimModel::sector ? spec.pinion_teeth_modelled * pinion_tooth.angular_pitch
                                   : 2. * M_PI,
      "rad", "angle spanned by the pinion body");
  add("wheel_sector_angle",
      spec.rim == RimModel::sector ? spec.wheel_teeth_modelled * wheel_tooth.angular_pitch
                                   : 2. * M_PI,
      "rad", "angle spanned by the wheel body");
  info.time_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return info;
}
} // namespace gearstiff::geometry
