// The gear-pair scene's bodies: each gear's nominal tooth and per-tooth outlines (modifications,
// faults), the rim to its bore (sector or full rim, pads, bolt holes), the checks of the scene's
// extent, and the planar model of both bodies with one boundary id per flank.
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/fields.h"
#include "geometry/gear_pair_internal.h"
#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_fault.h"
#include "geometry/tooth_modification_lead.h"
#include "kinematics/hertz.h"

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
InvoluteToothSpec tooth_spec(const kinematics::GearSpec& gear,
                             const kinematics::GearGeometry& derived)
{
  InvoluteToothSpec spec = involute_tooth_spec(gear, derived.tip_diameter);
  spec.required_form_diameter = derived.active_profile_start;
  return spec;
}

// The gear's nominal tooth, its errors naming the gear's fields.
ToothProfile gear_tooth(const kinematics::GearSpec& gear, const kinematics::GearGeometry& derived,
                        const ProfileResolution& resolution, bool wheel)
{
  return generate_gear_tooth(tooth_spec(gear, derived), resolution, wheel);
}

} // namespace

namespace detail
{
// Radius of the outline's first point, the middle of the root gap: where the rim begins.
double outline_root_radius(const ToothProfile& tooth)
{
  return tooth.points.front().position.norm();
}

// A contact surface: the involute (relieved or not) and a rounded tip edge's arc, which carries
// the contact where a contact line leaves the path of contact at the tip form circle.
bool is_flank(ProfileSegment segment)
{
  return segment == ProfileSegment::root_relief || segment == ProfileSegment::flank ||
         segment == ProfileSegment::relief || segment == ProfileSegment::tip_round;
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

} // namespace detail

namespace
{
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
  const bool wheel = body_spec.material_id == scene_ids::wheel_body;
  const std::string parameter = field::modified_gear(wheel);
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

} // namespace

namespace detail
{
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
  if (!(spec.pinion_torque > 0.))
    throw InputError(scene_field::pinion_torque, "must be positive");
  kinematics::check_young_modulus(spec.young_modulus, scene_field::young_modulus);
  kinematics::check_poisson_ratio(spec.poisson_ratio, scene_field::poisson_ratio);
}

} // namespace detail

namespace
{
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

} // namespace

FlankRollRange flank_roll_range(const kinematics::GearPairGeometry& pair, const ToothProfile& tooth,
                                bool wheel)
{
  const double rb = tooth.base_radius;
  const auto roll_at = [rb](double r) { return std::sqrt(std::max(0., r * r - rb * rb)); };
  FlankRollRange range;
  // The flank ends at the tip form circle (a rounded tip edge's arc begins there; sharp: the
  // tip circle), where the path of contact ends: tip reliefs are measured from there.
  range.tip = roll_at(tooth.tip_form_radius > 0. ? tooth.tip_form_radius : tooth.tip_radius);
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

void check_tooth_modifications(const GearPairSceneSpec& given)
{
  const GearPairSceneSpec spec = transverse_section_spec(given);
  if (spec.pinion_modifications.empty() && spec.wheel_modifications.empty())
    return;
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const ToothProfile pinion = gear_tooth(spec.pair.pinion, pair.pinion, spec.resolution, false);
  const ToothProfile wheel = gear_tooth(spec.pair.wheel, pair.wheel, spec.resolution, true);
  ToothProfiles(pinion, spec.pinion_modifications, flank_roll_range(pair, pinion, false),
                loaded_side(pinion), field::modified_gear(false));
  ToothProfiles(wheel, spec.wheel_modifications, flank_roll_range(pair, wheel, true),
                loaded_side(wheel), field::modified_gear(true));
  check_lead_modification(spec.pinion_modifications.lead, pinion, pair.common_face_width,
                          field::modified_gear(false));
  check_lead_modification(spec.wheel_modifications.lead, wheel, pair.common_face_width,
                          field::modified_gear(true));
}

namespace detail
{
// The nominal teeth of both gears and their per-tooth providers (modifications, faults).
PlacedGears generate_teeth(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair)
{
  PlacedGears gears;
  gears.pinion = gear_tooth(spec.pair.pinion, pair.pinion, spec.resolution, false);
  gears.wheel = gear_tooth(spec.pair.wheel, pair.wheel, spec.resolution, true);
  gears.pinion_teeth = ToothProfiles(gears.pinion, spec.pinion_modifications,
                                     flank_roll_range(pair, gears.pinion, false),
                                     loaded_side(gears.pinion), field::modified_gear(false));
  gears.wheel_teeth = ToothProfiles(gears.wheel, spec.wheel_modifications,
                                    flank_roll_range(pair, gears.wheel, true),
                                    loaded_side(gears.wheel), field::modified_gear(true));
  const auto whole = [](GearModifications modifications)
  {
    for (auto& [index, list] : modifications.by_tooth)
      list.erase(std::remove_if(list.begin(), list.end(), is_partial_width), list.end());
    return modifications;
  };
  gears.pinion_contact_teeth = ToothProfiles(
      gears.pinion, whole(spec.pinion_modifications), flank_roll_range(pair, gears.pinion, false),
      loaded_side(gears.pinion), field::modified_gear(false));
  gears.wheel_contact_teeth = ToothProfiles(gears.wheel, whole(spec.wheel_modifications),
                                            flank_roll_range(pair, gears.wheel, true),
                                            loaded_side(gears.wheel), field::modified_gear(true));
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

} // namespace detail
} // namespace gearstiff::geometry
