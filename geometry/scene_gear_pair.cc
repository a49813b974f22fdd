#include "geometry/scene_gear_pair.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/involute_tooth.h"
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

namespace gearstiff::geometry
{
namespace
{
// Contacts closer than this to the ends A, E of the path of contact still count (m): the
// zone ends come from the same floating-point formulas as the positions.
constexpr double path_tolerance = 1e-9;

InvoluteToothSpec tooth_spec(const kinematics::GearSpec& gear,
                             const kinematics::GearGeometry& derived)
{
  InvoluteToothSpec spec = involute_tooth_spec(gear, derived.tip_diameter);
  spec.required_form_diameter = derived.active_profile_start;
  return spec;
}

// The gear's nominal tooth. The generator knows one tooth, not which gear: its InputError
// ("Involute tooth/tip diameter") is renamed to the gear's own field ("Gear pair/Wheel/tip
// diameter"), the name the kinematics' checks of the same gear use.
ToothProfile gear_tooth(const kinematics::GearSpec& gear, const kinematics::GearGeometry& derived,
                        const ProfileResolution& resolution, bool wheel)
{
  try
  {
    return generate_involute_tooth(tooth_spec(gear, derived), resolution);
  }
  catch (const InputError& e)
  {
    const std::string generator = "Involute tooth/";
    if (e.parameter().rfind(generator, 0) != 0)
      throw;
    throw InputError(kinematics::gear_parameter_name(wheel, e.parameter().substr(generator.size())),
                     e.reason());
  }
}

// Radius of the outline's first point, the middle of the root gap: where the rim begins.
double outline_root_radius(const ToothProfile& tooth)
{
  return tooth.points.front().position.norm();
}

bool is_flank(ProfileSegment segment)
{
  return segment == ProfileSegment::root_relief || segment == ProfileSegment::flank ||
         segment == ProfileSegment::relief;
}

// The loaded flank of a tooth in its own frame (header comment): side +1 of the pinion and of
// an external wheel; an internal wheel turns with the pinion, and the pinion's leading flank
// pushes the ring tooth's −1 side.
int loaded_side(const ToothProfile& tooth)
{
  return tooth.internal ? -1 : +1;
}

// σ of involute_tooth.cc: +1 external, −1 internal (the involute unwinds the other way).
double involute_sign(const ToothProfile& tooth)
{
  return tooth.internal ? -1. : 1.;
}

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

Eigen::Vector2d place(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double rotation)
{
  return centre + Eigen::Rotation2Dd(rotation) * p;
}

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

// The pieces of one outline run `points` (placed by `placed`), a new piece wherever the segment
// or side of the outline changes (edge_between) or at a fault's kink (ProfilePoint::corner), so
// kinks (flank to tip, relief start) stay kinks and each piece carries one boundary id.
std::vector<BoundaryPiece>
outline_pieces(const std::vector<ProfilePoint>& points,
               const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& placed,
               const std::function<int(const ProfileEdge&)>& id_of)
{
  std::vector<BoundaryPiece> pieces;
  std::optional<ProfileEdge> previous;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    const ProfileEdge edge = edge_between(points[i], points[i + 1]);
    if (!previous || edge.segment != previous->segment || edge.side != previous->side ||
        points[i].corner)
    {
      pieces.emplace_back();
      pieces.back().kind = CurveKind::spline;
      pieces.back().boundary_id = id_of(edge);
      pieces.back().points.push_back(placed(points[i].position));
    }
    pieces.back().points.push_back(placed(points[i + 1].position));
    previous = edge;
  }
  return pieces;
}

// The piece of `pieces` (from `begin`) that starts (`at_start`) or ends at `point`.
std::optional<std::size_t> piece_at(const std::vector<BoundaryPiece>& pieces, std::size_t begin,
                                    const Eigen::Vector2d& point, bool at_start)
{
  for (std::size_t k = begin; k < pieces.size(); ++k)
    if (((at_start ? pieces[k].points.front() : pieces[k].points.back()) - point).norm() < 1e-9)
      return k;
  return std::nullopt;
}

// The fills of a faulty tooth (geometry/tooth_fault.h FaultFill: 3D partial-width faults, 2D
// cracks whose faces meet) as PlanarFill of its body, the tooth's pieces starting at `begin` in
// `pieces`. A crack's piece (mouth to tip) takes the boundary id crack_id(k).
void add_tooth_fills(const std::vector<FaultFill>& faults, int k, const Eigen::Vector2d& centre,
                     double angle, const std::function<int(const ProfileEdge&)>& id_of,
                     const std::function<int(int)>& crack_id, std::vector<BoundaryPiece>& pieces,
                     std::size_t begin, std::vector<PlanarFill>& fills)
{
  const auto placed = [&](const Eigen::Vector2d& p) { return place(p, centre, angle); };
  for (const FaultFill& fault : faults)
  {
    // The fill's corners in the outline's order (a spall's walls run either way); `closing`
    // runs from the end of the last piece back to the start of the first.
    std::vector<ProfilePoint> closing(fault.closing.rbegin(), fault.closing.rend());
    auto first = piece_at(pieces, begin, placed(fault.from), true);
    auto last = piece_at(pieces, begin, placed(fault.to), false);
    if (!first || !last || *first > *last)
    {
      first = piece_at(pieces, begin, placed(fault.to), true);
      last = piece_at(pieces, begin, placed(fault.from), false);
      closing.assign(fault.closing.begin(), fault.closing.end());
    }
    if (!first || !last || *first > *last)
      throw SolverFailure("gear scene fault",
                          "a partial fault's corners are not on the faulty tooth's outline");
    PlanarFill fill;
    fill.first_piece = *first;
    fill.last_piece = *last;
    if (fault.crack) // the cut: mouth → tip → end, or back; the crack is the piece at the mouth
    {
      const bool mouth_first = (pieces[*first].points.front() - placed(fault.from)).norm() < 1e-9;
      fill.crack_id = crack_id(k);
      pieces[mouth_first ? *first : *last].boundary_id = fill.crack_id;
      for (std::size_t p = *first; p <= *last; ++p)
        pieces[p].kind = CurveKind::straight;
    }
    fill.closing = outline_pieces(closing, placed, id_of);
    const Eigen::Rotation2Dd back(-angle);
    const auto removed = fault.removed;
    fill.removed = [removed, back, centre](const Eigen::Vector3d& x)
    { return removed(back * (x.head<2>() - centre), x.z()); };
    fills.push_back(fill);
  }
}

// The outline pieces of teeth `first`..`last` (indices CCW from tooth 0), placed; the flanks of
// tooth k carry flank_id(k), a crack whose faces meet crack_id(k). The fills of partial-width
// faults (3D, face_width > 0) and of cracks whose faces meet (2D).
std::vector<BoundaryPiece> teeth_pieces(const ToothProfiles& teeth, const Eigen::Vector2d& centre,
                                        double rotation, int first, int last,
                                        const std::function<int(int)>& flank_id,
                                        const std::function<int(int)>& crack_id, bool both_flanks,
                                        double face_width, const std::string& parameter,
                                        std::vector<PlanarFill>& fills)
{
  std::vector<BoundaryPiece> pieces;
  for (int k = first; k <= last; ++k)
  {
    // Each tooth is its own outline: the nominal one, or that with its modifications.
    const ToothProfile& tooth = teeth.tooth(k);
    const auto id_of = [&](const ProfileEdge& edge)
    {
      return (is_flank(edge.segment) && (edge.side == loaded_side(tooth) || both_flanks))
                 ? flank_id(k)
                 : 0;
    };
    const double angle = rotation + k * tooth.angular_pitch;
    const std::size_t begin = pieces.size();
    // The fills and a crack's cut start from the tooth the fault was cut from: the
    // profile-modified one (tip relief moves a chipped corner's and a spall's corners off the
    // nominal flank).
    const ToothProfile unfaulted = teeth.unfaulted_tooth(k);
    const std::vector<FaultFill> faults = fault_fills(
        unfaulted, teeth.modifications_of(k), loaded_side(unfaulted), face_width, parameter);
    const std::vector<ProfilePoint>* outline = &tooth.points; // a crack's cut replaces it
    for (const FaultFill& fault : faults)
      if (fault.crack)
        outline = &fault.outline;
    for (BoundaryPiece& piece : outline_pieces(
             *outline, [&](const Eigen::Vector2d& p) { return place(p, centre, angle); }, id_of))
      pieces.push_back(std::move(piece));
    add_tooth_fills(faults, k, centre, angle, id_of, crack_id, pieces, begin, fills);
  }
  // Consecutive teeth share their gap-middle point: the next tooth's first piece starts where
  // the previous tooth's last piece ends.
  return pieces;
}

struct GearBodySpec
{
  std::string name;
  int material_id, bore_id, cut_id;
  std::function<int(int)> flank_id; // of the tooth index in the gear's own frame
  double bore_radius;
  unsigned int supports = 0;      // -, full rim: 0 holds the whole bore circle, else N pads of it
  double support_width = 0.;      // m, arc length of one pad
  unsigned int bolt_holes = 0;    // -, ring: N clamped holes in the rim, the bore circle free
  double bolt_hole_radius = 0.;   // m
  double bolt_circle_radius = 0.; // m, of the hole centres
};

// Polar angle (about the gear's centre) of pad or bolt hole k of N: (k + ½)·2π/N, so that the
// pitch point (polar angle 0 about a ring's centre) lies midway between two.
double support_angle(unsigned int k, unsigned int count)
{
  return (k + 0.5) * 2. * M_PI / count;
}

// Appends `added` to `pieces`, starting it exactly where the last piece ends (angles that
// should coincide differ in the last bit once computed by two arcs).
void append_continuous(std::vector<BoundaryPiece>& pieces, std::vector<BoundaryPiece> added)
{
  if (!pieces.empty())
    added.front().points.front() = pieces.back().points.back();
  pieces.insert(pieces.end(), added.begin(), added.end());
}

// The bore circle of a full rim: held whole (`bore_id`), or only on N pads of arc length
// `support_width` centred at polar angles (k + ½)·2π/N about the centre, the arcs between them
// free. In the scene frame polar angle 0 about a ring's centre points at the pitch point, so the
// mesh lies midway between two pads: the rim there bends as a curved beam between its supports.
BoundaryLoop bore_loop(const GearBodySpec& body_spec, const Eigen::Vector2d& centre)
{
  if (body_spec.bolt_holes > 0) // bolted at holes in the rim: the outer circle is free
    return circle_loop(centre, body_spec.bore_radius, scene_ids::free_surface);
  if (body_spec.supports == 0)
    return circle_loop(centre, body_spec.bore_radius, body_spec.bore_id);
  BoundaryLoop loop;
  const double half_pad = 0.5 * body_spec.support_width / body_spec.bore_radius;
  const double spacing = 2. * M_PI / body_spec.supports;
  for (unsigned int k = 0; k < body_spec.supports; ++k)
  {
    const double middle = support_angle(k, body_spec.supports);
    append_continuous(loop.pieces, arc_pieces(centre, body_spec.bore_radius, middle - half_pad,
                                              middle + half_pad, body_spec.bore_id));
    append_continuous(loop.pieces,
                      arc_pieces(centre, body_spec.bore_radius, middle + half_pad,
                                 middle + spacing - half_pad, scene_ids::free_surface));
  }
  loop.pieces.back().points.back() = loop.pieces.front().points.front();
  return loop;
}

PlanarBody gear_body(const GearBodySpec& body_spec, const ToothProfiles& teeth,
                     const Eigen::Vector2d& centre, double rotation, int first, int last,
                     RimModel rim, bool both_flanks, double face_width)
{
  const ToothProfile& tooth = teeth.nominal();
  PlanarBody body;
  body.name = body_spec.name;
  body.material_id = body_spec.material_id;
  const std::string parameter =
      body_spec.material_id == scene_ids::pinion_body ? "Gear pair/Pinion" : "Gear pair/Wheel";
  const bool wheel = body_spec.material_id == scene_ids::wheel_body;
  body.outer.pieces = teeth_pieces(
      teeth, centre, rotation, first, last, body_spec.flank_id,
      [wheel](int k) { return crack_face_id(wheel, k); }, both_flanks, face_width, parameter,
      body.fills);
  const double root_radius = outline_root_radius(tooth);
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
    body.holes.push_back(bore_loop(body_spec, centre));
  }
  // A ring's "bore" is its outer boundary, the teeth line the hole it encloses; its bolt holes
  // (clamped: the hub) are further holes.
  if (tooth.internal && rim == RimModel::full)
  {
    body.outer.pieces.back().points.back() = outline_start;
    std::swap(body.outer, body.holes.front());
    for (unsigned int k = 0; k < body_spec.bolt_holes; ++k)
    {
      const double angle = support_angle(k, body_spec.bolt_holes);
      body.holes.push_back(circle_loop(
          centre + body_spec.bolt_circle_radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)),
          body_spec.bolt_hole_radius, body_spec.bore_id));
    }
    return body;
  }
  // The loop closes on the first point exactly (rotations by 2π are not bit-exact).
  body.outer.pieces.back().points.back() = outline_start;
  return body;
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

// Pads on a ring's outer circle: a full-rim internal wheel, at least two pads, each with a free
// arc at least as long as itself between it and the next (the outer radius is checked against
// the pads once it is known, in write_gear_pair_scene).
void check_wheel_supports(const GearPairSceneSpec& spec)
{
  if (spec.wheel_supports == 0)
    return;
  if (!spec.pair.wheel.internal || spec.rim != RimModel::full)
    throw InputError(scene_field::wheel_supports,
                     "applies to an internal wheel with a full rim only (0 otherwise)");
  if (spec.wheel_supports < 2)
    throw InputError(scene_field::wheel_supports,
                     "must be 0 (whole outer circle held) or at least 2 pads");
  // Features below limits::min_feature_size cannot be drawn (their outline repeats a point).
  if (!(spec.wheel_support_width >= limits::min_feature_size))
    throw InputError(scene_field::wheel_support_width, "must be at least 0.01 mm");
}

// Bolt holes in a ring's rim: a full-rim internal wheel, at least two holes, not with pads (the
// holes' fit in the rim is checked once the rim is known, in bolt_circle_radius).
void check_wheel_bolt_holes(const GearPairSceneSpec& spec)
{
  if (spec.wheel_bolt_holes == 0)
    return;
  if (!spec.pair.wheel.internal || spec.rim != RimModel::full)
    throw InputError(scene_field::wheel_bolt_holes,
                     "applies to an internal wheel with a full rim only (0 otherwise)");
  if (spec.wheel_bolt_holes < 2)
    throw InputError(scene_field::wheel_bolt_holes,
                     "must be 0 (no holes) or at least 2 bolt holes");
  if (spec.wheel_supports > 0)
    throw InputError(scene_field::wheel_bolt_holes,
                     "a ring is held either at pads (wheel supports) or at bolt holes, not both");
  if (!(spec.wheel_bolt_hole_diameter >= limits::min_feature_size))
    throw InputError(scene_field::wheel_bolt_hole_diameter, "must be at least 0.01 mm");
  if (!(spec.wheel_bolt_circle_diameter >= 0.))
    throw InputError(scene_field::wheel_bolt_circle_diameter, "must be 0 or positive");
}

// Radius of the bolt-hole centres (m; 0 without holes) in the ring's rim between its root
// circle and its outer circle. Every hole keeps at least one module of material towards the
// root circle (the fillets and the tooth roots lie inside it: as the rim rule of bore_radius),
// towards the outer circle and towards its neighbours.
double bolt_circle_radius(const GearPairSceneSpec& spec, double root_radius, double outer_radius)
{
  if (spec.wheel_bolt_holes == 0)
    return 0.;
  const double ligament = spec.pair.wheel.normal_module;
  const double hole_radius = 0.5 * spec.wheel_bolt_hole_diameter;
  const double radius = spec.wheel_bolt_circle_diameter > 0. ? 0.5 * spec.wheel_bolt_circle_diameter
                                                             : 0.5 * (root_radius + outer_radius);
  const auto mm = [](double length) { return std::to_string(length * 1e3) + " mm"; };
  if (radius - hole_radius < root_radius + ligament)
    throw InputError(spec.wheel_bolt_circle_diameter > 0. ? scene_field::wheel_bolt_circle_diameter
                                                          : scene_field::wheel_bolt_hole_diameter,
                     "the holes (radius " + mm(hole_radius) + " on a " + mm(radius) +
                         " circle) reach within one module (" + mm(ligament) +
                         ") of the ring's root circle (radius " + mm(root_radius) +
                         "): they would cut the teeth");
  if (radius + hole_radius > outer_radius - ligament)
    throw InputError(spec.wheel_bolt_circle_diameter > 0. ? scene_field::wheel_bolt_circle_diameter
                                                          : scene_field::wheel_bolt_hole_diameter,
                     "the holes (radius " + mm(hole_radius) + " on a " + mm(radius) +
                         " circle) break out of the rim: they must end one module (" +
                         mm(ligament) + ") inside its outer circle (radius " + mm(outer_radius) +
                         ")");
  if (2. * radius * std::sin(M_PI / spec.wheel_bolt_holes) < 2. * hole_radius + ligament)
    throw InputError(scene_field::wheel_bolt_holes,
                     std::to_string(spec.wheel_bolt_holes) + " holes of " + mm(2. * hole_radius) +
                         " on a " + mm(radius) +
                         " circle overlap or leave less than one module between neighbours");
  return radius;
}

// The pads and the free arcs between them fit on the ring's outer circle of `radius` (m).
void check_support_spacing(const GearPairSceneSpec& spec, double radius)
{
  if (spec.wheel_supports > 0 &&
      2. * spec.wheel_supports * spec.wheel_support_width > 2. * M_PI * radius)
    throw InputError(scene_field::wheel_support_width,
                     "leaves less free rim than pad between the " +
                         std::to_string(spec.wheel_supports) + " pads on the outer circle (" +
                         std::to_string(2. * M_PI * radius * 1e3) + " mm long)");
}

// The spec's own checks (the pair's are kinematics'): load, material, flank choice.
void check_scene_spec(const GearPairSceneSpec& spec)
{
  if (!(spec.wheel_rim_thickness >= 0.))
    throw InputError(scene_field::wheel_rim_thickness, "must be 0 or positive");
  if (spec.wheel_rim_thickness > 0. && !spec.pair.wheel.internal)
    throw InputError(scene_field::wheel_rim_thickness,
                     "applies to an internal wheel only (external gears: bore radius)");
  check_wheel_supports(spec);
  check_wheel_bolt_holes(spec);
  if (spec.pair.pinion.helix_angle != 0. || spec.pair.wheel.helix_angle != 0.)
    throw InputError(kinematics::gear_parameter_name(false, "helix angle"),
                     "the gear-pair scene models spur gears only (helix angle 0)");
  if (!(spec.pinion_torque > 0.))
    throw InputError(scene_field::pinion_torque, "must be positive");
  if (!(spec.young_modulus > 0.))
    throw InputError(scene_field::young_modulus, "must be positive");
  if (!(spec.poisson_ratio > 0. && spec.poisson_ratio < 0.5))
    throw InputError(scene_field::poisson_ratio, "must lie in (0, 0.5)");
}

// The bore radius of one gear (internal wheel: the outer radius of its rim): the rim
// thickness, else the scene's own radius, else half the gear's bore diameter. The rim under the
// root must keep at least one module of material, or its mesh degenerates into a sliver.
double bore_radius(double given, double rim_thickness, const kinematics::GearSpec& gear, bool wheel,
                   const ToothProfile& tooth, const std::string& field)
{
  const double root_radius = outline_root_radius(tooth);
  const double sigma = involute_sign(tooth);
  const double radius = rim_thickness > 0. ? root_radius + rim_thickness
                        : given > 0.       ? given
                                           : 0.5 * gear.bore_diameter;
  const std::string parameter = rim_thickness > 0. ? scene_field::wheel_rim_thickness
                                : given > 0.
                                    ? field
                                    : kinematics::gear_parameter_name(wheel, "bore diameter");
  if (!(radius > 0.))
    throw InputError(parameter, std::string("must be positive (no ") +
                                    (gear.internal ? "outer diameter" : "bore") +
                                    " given for the gear)");
  if (sigma * (root_radius - radius) < gear.normal_module)
  {
    // The nearest value that keeps one module, as the parameter writes it.
    const double limit = root_radius - sigma * gear.normal_module;
    const std::string suggestion =
        parameter == scene_field::wheel_rim_thickness ? "at least " + format_mm(gear.normal_module)
        : parameter == field
            ? (gear.internal ? "at least " : "at most ") + format_mm(limit)
            : (gear.internal ? "an outer diameter of at least " : "a bore diameter of at most ") +
                  format_mm(2. * limit) + ", or auto";
    throw InputError(parameter, "leaves a rim thinner than one module (" +
                                    std::to_string(gear.normal_module * 1e3) +
                                    " mm) under the root circle (root radius " +
                                    std::to_string(root_radius * 1e3) + " mm): use " + suggestion);
  }
  return radius;
}

void check_teeth_modelled(unsigned int count, unsigned int teeth, RimModel rim,
                          const std::string& field)
{
  const unsigned int limit = rim == RimModel::sector ? teeth - 1 : teeth;
  if (count < 1 || count > limit)
    throw InputError(field, "must lie between 1 and " + std::to_string(limit) +
                                (rim == RimModel::sector ? " (sector rim)" : ""));
}

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

// The line of action (header comment): T1 on the pinion base circle, direction u.
struct LineOfAction
{
  Eigen::Vector2d t1, u;
  double t2; // m, T2 from T1 (internal pair: behind T1, negative)
  Eigen::Vector2d at(double position) const { return t1 + position * u; }
};

LineOfAction line_of_action(const kinematics::GearPairGeometry& pair)
{
  const double alpha = pair.working_pressure_angle;
  const double base_radius_1 = 0.5 * pair.pinion.base_diameter;
  return {base_radius_1 * Eigen::Vector2d(std::cos(alpha), -std::sin(alpha)),
          Eigen::Vector2d(std::sin(alpha), std::cos(alpha)),
          pair.spec.wheel.internal ? -pair.line_of_action_length : pair.line_of_action_length};
}

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

// The wheel tooth that meshes pinion tooth j: −j on an external wheel (it turns the other
// way), +j on a ring (it turns with the pinion).
int mate_tooth(const ToothProfile& wheel, int j)
{
  return wheel.internal ? j : -j;
}

// Predicted contact of pair j with its Hertz estimate and its initial gap measured between the
// placed flank outlines along the line of action.
SceneContact predicted_contact(const GearPairSceneSpec& spec,
                               const kinematics::GearPairGeometry& pair, const LineOfAction& line,
                               const PlacedGears& gears, double reference, int j,
                               double normal_force)
{
  SceneContact contact;
  const double position = reference + j * pair.transverse_base_pitch;
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
      gears.pinion_rotation + j * gears.pinion.angular_pitch, contact.point, line.u);
  const auto on_wheel = flank_intersection(
      gears.wheel_contact_teeth.tooth(mate_tooth(gears.wheel, j)), gears.wheel_centre,
      gears.wheel_rotation + mate_tooth(gears.wheel, j) * gears.wheel.angular_pitch, contact.point,
      line.u);
  if (!on_pinion || !on_wheel)
    throw SolverFailure("gear scene placement",
                        "the line of action misses a flank of pair " + std::to_string(j));
  contact.gap = *on_wheel - *on_pinion;
  return contact;
}
// Rolling sweeps: the pairs in contact at the scene's position or at one of the swept ones.
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
    for (const int j : pairs_in_contact(pair, position))
      pairs.push_back(j);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
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
    const double at = position + j * pair.transverse_base_pitch;
    separations.push_back(
        gears.pinion_teeth.loaded_flank_removal(j, at) +
        gears.wheel_teeth.loaded_flank_removal(mate_tooth(gears.wheel, j), std::abs(at - line.t2)) +
        lead);
  }
  return separations;
}

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
// Lead modifications (3D, geometry/tooth_modification_lead.h): the extruded nodes of each gear
// turned about its axis by their removal; empty without lead modifications.
std::function<Eigen::Vector2d(int, const Eigen::Vector3d&)>
lead_offsets(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
             const PlacedGears& gears)
{
  return lead_node_offset(
      spec.mesh.dimension,
      {{scene_ids::pinion_body,
        LeadModifier(gears.pinion, spec.pinion_modifications.lead, loaded_side(gears.pinion),
                     pair.common_face_width, gears.pinion_centre, gears.pinion_rotation,
                     "Gear pair/Pinion")},
       {scene_ids::wheel_body,
        LeadModifier(gears.wheel, spec.wheel_modifications.lead, loaded_side(gears.wheel),
                     pair.common_face_width, gears.wheel_centre, gears.wheel_rotation,
                     "Gear pair/Wheel")}},
      {"Gear pair/Pinion", "Gear pair/Wheel"});
}
} // namespace

std::vector<int> gear_pairs_in_contact(const kinematics::GearPairGeometry& pair, double position)
{
  return pairs_in_contact(pair, position);
}

Eigen::Vector2d line_of_action_point(const kinematics::GearPairGeometry& pair, double position)
{
  return line_of_action(pair).at(position);
}

FlankRollRange flank_roll_range(const kinematics::GearPairGeometry& pair, const ToothProfile& tooth,
                                bool wheel)
{
  const double rb = tooth.base_radius;
  const auto roll_at = [rb](double r) { return std::sqrt(std::max(0., r * r - rb * rb)); };
  FlankRollRange range;
  range.tip = roll_at(tooth.tip_radius);
  range.form = roll_at(tooth.form_radius);
  const double a = pair.contact_start, e = pair.contact_end;
  const double b = pair.single_contact_start(), d = pair.single_contact_end();
  if (!wheel)
  {
    range.active_root = a;
    range.active_tip = e;
    range.single_root = b;
    range.single_tip = d;
    return range;
  }
  // The wheel's roll length of a point ℓ of the line of action: its distance from T2.
  const double t2 = line_of_action(pair).t2;
  const auto on_wheel = [t2](double position) { return std::abs(position - t2); };
  range.active_tip = on_wheel(a); // the wheel tip meets the pinion at A
  range.active_root = on_wheel(e);
  range.single_tip = on_wheel(b);
  range.single_root = on_wheel(d);
  return range;
}

int pinion_flank_id(int pair)
{
  if (std::abs(pair) > max_pair_index)
    throw SolverFailure("gear scene ids",
                        "tooth pair index " + std::to_string(pair) + " out of range");
  return 200 + pair;
}

int wheel_flank_id(int pair)
{
  return pinion_flank_id(pair) + 200;
}

int crack_face_id(bool wheel, int tooth)
{
  if (std::abs(tooth) > max_pair_index)
    throw SolverFailure("gear scene ids", "tooth index " + std::to_string(tooth) + " out of range");
  return 1000 + (wheel ? 400 : 0) + 2 * (tooth + max_pair_index);
}

RimModel parse_rim_model(const std::string& text, const std::string& parameter)
{
  if (text == "sector")
    return RimModel::sector;
  if (text == "full")
    return RimModel::full;
  throw InputError(parameter, "'" + text + "' is not one of sector, full");
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

void check_tooth_modifications(const GearPairSceneSpec& spec)
{
  if (spec.pinion_modifications.empty() && spec.wheel_modifications.empty())
    return;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const ToothProfile pinion = gear_tooth(spec.pair.pinion, pair.pinion, spec.resolution, false);
  const ToothProfile wheel = gear_tooth(spec.pair.wheel, pair.wheel, spec.resolution, true);
  ToothProfiles(pinion, spec.pinion_modifications, flank_roll_range(pair, pinion, false),
                loaded_side(pinion), "Gear pair/Pinion");
  ToothProfiles(wheel, spec.wheel_modifications, flank_roll_range(pair, wheel, true),
                loaded_side(wheel), "Gear pair/Wheel");
  check_lead_modification(spec.pinion_modifications.lead, pinion, pair.common_face_width,
                          "Gear pair/Pinion");
  check_lead_modification(spec.wheel_modifications.lead, wheel, pair.common_face_width,
                          "Gear pair/Wheel");
}

namespace
{
// The nominal teeth of both gears and their per-tooth providers (modifications, faults).
PlacedGears generate_teeth(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair)
{
  PlacedGears gears;
  gears.pinion = gear_tooth(spec.pair.pinion, pair.pinion, spec.resolution, false);
  gears.wheel = gear_tooth(spec.pair.wheel, pair.wheel, spec.resolution, true);
  gears.pinion_teeth = ToothProfiles(gears.pinion, spec.pinion_modifications,
                                     flank_roll_range(pair, gears.pinion, false),
                                     loaded_side(gears.pinion), "Gear pair/Pinion");
  gears.wheel_teeth = ToothProfiles(gears.wheel, spec.wheel_modifications,
                                    flank_roll_range(pair, gears.wheel, true),
                                    loaded_side(gears.wheel), "Gear pair/Wheel");
  const auto whole = [](GearModifications modifications)
  {
    for (auto& [index, list] : modifications.by_tooth)
      list.erase(std::remove_if(list.begin(), list.end(), is_partial_width), list.end());
    return modifications;
  };
  gears.pinion_contact_teeth = ToothProfiles(gears.pinion, whole(spec.pinion_modifications),
                                             flank_roll_range(pair, gears.pinion, false),
                                             loaded_side(gears.pinion), "Gear pair/Pinion");
  gears.wheel_contact_teeth = ToothProfiles(gears.wheel, whole(spec.wheel_modifications),
                                            flank_roll_range(pair, gears.wheel, true),
                                            loaded_side(gears.wheel), "Gear pair/Wheel");
  return gears;
}

// Bore (rim) radii, pads and bolt holes, and the teeth counts: all checked before gmsh runs.
void set_rims(const GearPairSceneSpec& spec, const PlacedGears& gears, GearPairScene& scene)
{
  scene.pinion_bore_radius = bore_radius(spec.pinion_bore_radius, 0., spec.pair.pinion, false,
                                         gears.pinion, scene_field::pinion_bore_radius);
  scene.wheel_bore_radius =
      bore_radius(spec.wheel_bore_radius, spec.wheel_rim_thickness, spec.pair.wheel, true,
                  gears.wheel, scene_field::wheel_bore_radius);
  check_support_spacing(spec, scene.wheel_bore_radius);
  scene.wheel_bolt_circle_radius =
      bolt_circle_radius(spec, outline_root_radius(gears.wheel), scene.wheel_bore_radius);
  check_teeth_modelled(spec.pinion_teeth_modelled, spec.pair.pinion.teeth, spec.rim,
                       scene_field::pinion_teeth_modelled);
  check_teeth_modelled(spec.wheel_teeth_modelled, spec.pair.wheel.teeth, spec.rim,
                       scene_field::wheel_teeth_modelled);
}

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
  scene.contact_pairs = pairs_in_contact(pair, scene.reference_position);
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
                           (spec.swept_positions.empty() ? "" : " or one the sweep turns to"));
}

// Placement: the loaded flanks of pair 0 through the reference point. An external wheel sits
// beyond the pitch point, a ring's centre on the other side of the pinion's (the pitch point lies
// on the ring's pitch circle, outside the pinion).
void place_gears(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                 const LineOfAction& line, double reference, PlacedGears& gears)
{
  const Eigen::Vector2d reference_point = line.at(reference);
  gears.pinion_centre = Eigen::Vector2d(0., 0.);
  gears.wheel_centre =
      Eigen::Vector2d(spec.pair.wheel.internal ? -pair.centre_distance : pair.centre_distance, 0.);
  gears.pinion_rotation = placing_rotation(gears.pinion, gears.pinion_centre, reference_point);
  gears.wheel_rotation = placing_rotation(gears.wheel, gears.wheel_centre, reference_point);
}

// The teeth in the scene: windows of pair indices centred on the contacting pairs.
struct ModelWindows
{
  int pinion_first = 0, pinion_last = 0;         // pinion tooth indices
  int wheel_first_pair = 0, wheel_last_pair = 0; // pair indices j of the wheel's teeth
  int wheel_first = 0, wheel_last = 0;           // wheel tooth indices (its own frame)
};

// A faulty tooth outside the modelled teeth would be silently healthy: refused by its index.
void check_faulty_teeth_modelled(const GearModifications& modifications, int first, int last,
                                 const std::string& gear)
{
  for (const auto& [index, list] : modifications.by_tooth)
    if (has_faults(list) && (index < first || index > last))
      throw InputError("Gear pair/" + gear + "/faulty tooth",
                       "tooth " + std::to_string(index) + " is not among the modelled teeth (" +
                           std::to_string(first) + " to " + std::to_string(last) +
                           ") at this position");
}

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
  check_faulty_teeth_modelled(spec.pinion_modifications, w.pinion_first, w.pinion_last, "Pinion");
  check_faulty_teeth_modelled(spec.wheel_modifications, w.wheel_first, w.wheel_last, "Wheel");
  return w;
}

// Both bodies with one boundary id per flank, and the physical names.
PlanarModel gear_pair_model(const GearPairSceneSpec& spec, const PlacedGears& gears,
                            const GearPairScene& scene, const ModelWindows& w, double face_width)
{
  // Partial-width faults are fills of the extruded mesh (3D only); cracks whose faces meet are
  // fills in 2D.
  const double fill_width = spec.mesh.dimension == 3 ? face_width : 0.;
  PlanarModel model;
  model.bodies.push_back(
      gear_body({"pinion body", scene_ids::pinion_body, scene_ids::pinion_bore,
                 scene_ids::pinion_cuts, pinion_flank_id, scene.pinion_bore_radius},
                gears.pinion_teeth, gears.pinion_centre, gears.pinion_rotation, w.pinion_first,
                w.pinion_last, spec.rim, spec.both_flanks, fill_width));
  const ToothProfile& wheel_tooth = gears.wheel;
  model.bodies.push_back(gear_body(
      {"wheel body", scene_ids::wheel_body, scene_ids::wheel_bore, scene_ids::wheel_cuts,
       [&wheel_tooth](int k) { return wheel_flank_id(mate_tooth(wheel_tooth, k)); },
       scene.wheel_bore_radius, spec.wheel_supports, spec.wheel_support_width,
       spec.wheel_bolt_holes, 0.5 * spec.wheel_bolt_hole_diameter, scene.wheel_bolt_circle_radius},
      gears.wheel_teeth, gears.wheel_centre, gears.wheel_rotation, w.wheel_first, w.wheel_last,
      spec.rim, spec.both_flanks, fill_width));
  model.boundary_names = {{scene_ids::pinion_bore, "pinion bore"},
                          {scene_ids::wheel_bore, "wheel bore"}};
  for (int j = w.pinion_first; j <= w.pinion_last; ++j)
    model.boundary_names[pinion_flank_id(j)] = "pinion flank " + std::to_string(j);
  for (int j = w.wheel_first_pair; j <= w.wheel_last_pair; ++j)
    model.boundary_names[wheel_flank_id(j)] = "wheel flank " + std::to_string(j);
  for (const PlanarBody& body : model.bodies)
    for (const PlanarFill& fill : body.fills)
      for (const int id : {fill.crack_id, fill.crack_id + 1})
        if (fill.crack_id > 0)
          model.boundary_names[id] = body.name + " crack face " + std::to_string(id);
  if (spec.rim == RimModel::sector)
  {
    model.boundary_names[scene_ids::pinion_cuts] = "pinion sector cuts";
    model.boundary_names[scene_ids::wheel_cuts] = "wheel sector cuts";
  }
  return model;
}

// Where the faults of the modelled teeth need a finer mesh (a crack's faces and tip), placed.
std::vector<SizeFocus> placed_fault_foci(const ToothProfiles& teeth, const Eigen::Vector2d& centre,
                                         double rotation, int first, int last)
{
  std::vector<SizeFocus> foci;
  for (int k = first; k <= last; ++k)
    for (SizeFocus focus :
         fault_foci(teeth.modifications_of(k), teeth.nominal(), loaded_side(teeth.nominal())))
    {
      focus.point = place(focus.point, centre, rotation + k * teeth.nominal().angular_pitch);
      foci.push_back(focus);
    }
  return foci;
}

// Meshes the model. The rims only carry the tooth loads to the bore: their cells may grow with
// depth below the root circle, which keeps a thin-rimmed wheel sector from dominating the cell
// count.
void mesh_gear_pair(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                    const PlacedGears& gears, const ModelWindows& w, const PlanarModel& model,
                    const std::vector<SceneContact>& contacts, const std::string& file,
                    GearPairScene& scene)
{
  scene.pinion_root_radius = outline_root_radius(gears.pinion);
  scene.wheel_root_radius = outline_root_radius(gears.wheel);
  const auto depth_below_root = [&](const Eigen::Vector2d& x)
  {
    return std::max(scene.pinion_root_radius - (x - gears.pinion_centre).norm(),
                    involute_sign(gears.wheel) *
                        (scene.wheel_root_radius - (x - gears.wheel_centre).norm()));
  };
  std::vector<SizeFocus> foci =
      placed_fault_foci(gears.pinion_teeth, gears.pinion_centre, gears.pinion_rotation,
                        w.pinion_first, w.pinion_last);
  const std::vector<SizeFocus> wheel_foci = placed_fault_foci(
      gears.wheel_teeth, gears.wheel_centre, gears.wheel_rotation, w.wheel_first, w.wheel_last);
  foci.insert(foci.end(), wheel_foci.begin(), wheel_foci.end());
  // A rolling sweep's band of foci along every flank (add_swept_contacts): gmsh's longest edges
  // at the foci reached 1.0798 times the size at the usual first scale of 0.6 (default pair,
  // 128 positions), so the band was meshed twice, the second time at 0.6·0.95/1.0798. The band
  // starts at that scale: the same mesh, generated once (a band whose edges still overshoot is
  // generated again finer, as before). 2D only: the 3D band's accuracy was measured on the
  // meshes from the first scale of 0.6 (test_sweep_once.ThreeDQ1).
  SceneMeshSettings mesh = spec.mesh;
  if (!spec.swept_positions.empty() && spec.mesh.dimension == 2)
    mesh.initial_contact_scale = 0.6 * (0.95 / 1.0798158575774983);
  scene.info =
      mesh_scene(model, contacts, mesh, pair.common_face_width, file, depth_below_root, foci);
}

// The scene's own numbers in SceneInfo (centres, rotations, line of action, quantities).
void describe_scene(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                    const LineOfAction& line, const PlacedGears& gears, GearPairScene& scene)
{
  SceneInfo& info = scene.info;
  info.kind = "gear pair";
  info.first_centre = gears.pinion_centre;
  info.second_centre = gears.wheel_centre;
  info.first_rotation = gears.pinion_rotation;
  info.second_rotation = gears.wheel_rotation;
  info.reference_line = {line.at(std::min(0., line.t2)),
                         line.at(std::max(line.t2, pair.contact_end))};
  scene.pinion_roll_angle = scene.reference_position / (0.5 * pair.pinion.base_diameter);
  scene.pinion_tip_radius = gears.pinion.tip_radius;
  scene.wheel_tip_radius = gears.wheel.tip_radius;
  scene.pinion_sector_angle = spec.rim == RimModel::sector
                                  ? spec.pinion_teeth_modelled * gears.pinion.angular_pitch
                                  : 2. * M_PI;
  scene.wheel_sector_angle = spec.rim == RimModel::sector
                                 ? spec.wheel_teeth_modelled * gears.wheel.angular_pitch
                                 : 2. * M_PI;
  info.quantities = scene_quantities(scene);
  info.quantities.insert(info.quantities.begin(),
                         {{"centre_distance", pair.centre_distance, "m", "centre distance a_w"},
                          {"working_pressure_angle", pair.working_pressure_angle, "rad",
                           "working pressure angle α_wt"},
                          {"pinion_teeth_modelled", double(spec.pinion_teeth_modelled), "-",
                           "pinion teeth in the scene"},
                          {"wheel_teeth_modelled", double(spec.wheel_teeth_modelled), "-",
                           "wheel teeth in the scene"}});
  if (!spec.pinion_modifications.empty() || !spec.wheel_modifications.empty())
    info.quantities.push_back({"unloaded_transmission_error", scene.unloaded_transmission_error,
                               "m", "the modifications' kinematic error at this position"});
}
} // namespace

std::vector<int> carrying_gear_pairs(const GearPairSceneSpec& spec, double position)
{
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

std::vector<double> unloaded_transmission_errors(const GearPairSceneSpec& spec,
                                                 const std::vector<double>& positions)
{
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const PlacedGears gears = generate_teeth(spec, pair);
  const LineOfAction line = line_of_action(pair);
  std::vector<double> errors;
  for (const double position : positions)
  {
    const std::vector<double> separations =
        pair_separations(spec, pair, line, gears, position, pairs_in_contact(pair, position));
    if (separations.empty())
      throw InputError(scene_field::swept_positions, "no tooth pair is in contact at " +
                                                         format_number(position * 1e3, 6) +
                                                         " mm along the line of action");
    errors.push_back(*std::min_element(separations.begin(), separations.end()));
  }
  return errors;
}

GearPairScene write_gear_pair_scene(const GearPairSceneSpec& spec, const std::string& file)
{
  const auto start = std::chrono::steady_clock::now();
  // Everything is checked before gmsh runs: the pair itself (interference, backlash, contact
  // ratio) by the kinematics, the scene's own extent here.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  check_scene_spec(spec);
  PlacedGears gears = generate_teeth(spec, pair);
  GearPairScene scene;
  set_rims(spec, gears, scene);

  const LineOfAction line = line_of_action(pair);
  locate_pairs(spec, pair, line, gears, scene);
  place_gears(spec, pair, line, scene.reference_position, gears);
  const double normal_force =
      spec.pinion_torque / (0.5 * pair.pinion.base_diameter) / scene.contact_pairs.size();
  std::vector<SceneContact> contacts;
  for (const int j : scene.contact_pairs)
    contacts.push_back(
        predicted_contact(spec, pair, line, gears, scene.reference_position, j, normal_force));
  set_unloaded_transmission_error(spec, pair, line, gears, scene);
  if (!spec.swept_positions.empty())
    add_swept_contacts(spec, pair, line, gears, scene.reference_position, contacts);

  const ModelWindows windows = model_windows(spec, gears, scene);
  PlanarModel model = gear_pair_model(spec, gears, scene, windows, pair.common_face_width);
  model.node_offset = lead_offsets(spec, pair, gears);
  mesh_gear_pair(spec, pair, gears, windows, model, contacts, file, scene);
  describe_scene(spec, pair, line, gears, scene);
  scene.info.time_total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}

std::vector<SceneQuantity> scene_quantities(const GearPairScene& scene)
{
  return {
      {"reference_contact_position", scene.reference_position, "m",
       "reference contact, distance from T1"},
      {"pinion_roll_angle", scene.pinion_roll_angle, "rad", "pinion roll angle ℓ/r_b1"},
      {"pairs_in_contact", double(scene.contact_pairs.size()), "-", "tooth pairs in contact"},
      {"modelled_pairs", double(scene.modelled_pairs.size()), "-",
       "tooth pairs with both teeth in the scene"},
      {"pinion_bore_radius", scene.pinion_bore_radius, "m", "pinion bore radius"},
      {"wheel_bore_radius", scene.wheel_bore_radius, "m", "wheel bore radius"},
      {"pinion_root_radius", scene.pinion_root_radius, "m",
       "pinion root radius (rim outer radius)"},
      {"wheel_root_radius", scene.wheel_root_radius, "m", "wheel root radius (rim outer radius)"},
      {"pinion_tip_radius", scene.pinion_tip_radius, "m", "pinion tip radius"},
      {"wheel_tip_radius", scene.wheel_tip_radius, "m", "wheel tip radius"},
      {"pinion_sector_angle", scene.pinion_sector_angle, "rad", "angle spanned by the pinion body"},
      {"wheel_sector_angle", scene.wheel_sector_angle, "rad", "angle spanned by the wheel body"}};
}
} // namespace gearstiff::geometry
